// Truncated power series in one variable, for the singular module's series algebra on
// half-branches (tangent_plane_expansion.cpp, collapsed_row_chart.cpp): coefficients 0..order in
// a std::vector (order = size - 1; core/jet.hpp stops at order 12 and has no reversion).
// Sources: Knuth, TAOCP vol. 2 §4.7 (powers of a series by J. C. P. Miller's recurrence,
// composition, reversion).
#pragma once

#include <vector>

#include "ssimarch/singular/local_jet.hpp"

namespace ssimarch::series {

using Series = std::vector<double>;

/// a b, truncated to a's order.
Series product(const Series& a, const Series& b);

/// |a| coefficient-wise (for majorants: bounds on the terms summed into each coefficient).
Series absolute(Series a);

/// p(s(x), t(x)) for a bivariate jet p, to the series' order; s and t vanish to order `low` >= 1
/// (the degrees beyond order / low do not reach it). With `majorant`, sum |coef| |s|^i |t|^j.
Series compose(const LocalJet& p, const Series& s, const Series& t, int low, bool majorant = false);

/// g^alpha for g with g[0] > 0 (Miller's recurrence: alpha g' g^alpha = g (g^alpha)').
Series power(const Series& g, double alpha);

/// f^0 .. f^order for f with f[0] = 0.
std::vector<Series> powers(const Series& f);

/// a(f) = sum a_k f^k from the powers of f (`powers`), to the powers' order.
Series substitute(const Series& a, const std::vector<Series>& fp);

/// The inverse x(y) of y(x) = y_1 x + y_2 x^2 + ... (y_0 = 0, y_1 != 0), to the same order.
Series revert(const Series& y);

}  // namespace ssimarch::series
