// Classification of a singular point of a plane curve germ h(s, t) = 0 (thesis ch. 5 §5.2.2-
// §5.2.5 and §2.3-2.4; the tangent, codimension and coefficient paradigms):
//   * multiplicity m = the lowest degree of h, and the tangent cone: real lines of the degree-m form;
//   * the Milnor number mu = dim R[[s,t]] / (h_s, h_t) (the thesis' codimension), by exact linear
//     algebra on the truncated Jacobian ideal (Gibson's monomial pyramid done by rank, as the
//     oracle singularity_tools.py): the first N with dim Q/(J + M^N) = dim Q/(J + M^(N+1)) gives
//     M^N in J by Nakayama, so mu = dim Q/(J + M^N);
//   * corank 1: the splitting lemma on the jet (Prop 2.12-2.14): with the Hessian's non-zero
//     eigenvalue lambda along X and its kernel along Y, solve h_X(X(Y), Y) = 0 as a series;
//     h(X(Y), Y) = c Y^(k+1) + ... gives A_k; k odd has two real branches iff c lambda < 0 (§4.4);
//   * corank 2: D4 (three distinct lines of the cubic, real or not), D_mu (a double line),
//     E_6/E_7/E_8 (a triple line), X9 (ordinary quadruple point), by mu and the cone.
// A germ whose Milnor number does not stabilise within the jet has a non-isolated singular set
// (a squared factor): a curve of tangential contact, crossed by a transversal branch when m >= 3.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/local_jet.hpp"

namespace ssimarch {

enum class SingularType {
  kRegular,              // grad h != 0: not a singular point
  kNode,                 // A1 with two real branches crossing
  kIsolated,             // no real branch through the point (A1, A3, A5, ... of real form x^2 + y^(k+1))
  kCusp,                 // A2
  kTacnode,              // A3 with two real branches touching
  kRamphoidCusp,         // A4
  kOscnode,              // A5 with two real branches (third-order contact, crossing)
  kHigherDoublePoint,    // A_k, 6 <= k <= kLocalOrder - 1 (name: higher_double_point)
  kTriplePoint,          // multiplicity 3 (D4 with three or one real line, D_k, E6-E8)
  kQuadruplePoint,       // multiplicity 4
  kMultiplePoint,        // multiplicity >= 5
  kTangentLineCrossing,  // a transversal branch crossing a curve of tangential contact
  kTangentialContact,    // a point of a curve of tangential contact (double line, no crossing)
};
/// "regular", "node", "isolated", "cusp", "tacnode", "ramphoid_cusp", "oscnode",
/// "higher_double_point", "triple_point", "quadruple_point", "multiple_point",
/// "tangent_line_crossing", "tangential_contact".
std::string_view to_string(SingularType t);

struct ClassifyOptions {
  // Coefficients of h below zero_tolerance * (largest |coefficient| of degree >= 2) are zero
  // (relative; thesis §5.2.5 coefficient tests, done as exact zero tests with a tolerance relative to the coefficient scale).
  double zero_tolerance = kClassifyZeroTolerance;
  // The germ length (model units, > 0): h is classified as h(length S, length T) / length, so
  // that coefficients of different degrees are weighed over a disc of this radius
  // (kGermLengthRatio x the model size for an intersection; 1 for a germ given in its own units).
  double length = 1.0;
};

/// A real line of the tangent cone: unit direction in (s, t) and multiplicity as a root of the
/// lowest homogeneous form.
using TangentLine = FormRoot;

struct Classification {
  SingularType type = SingularType::kRegular;
  std::string ak;         // "A1".."A11", "D4".., "E6", "E7", "E8", "X9"; empty where none applies
  int multiplicity = 1;   // lowest degree of h
  int milnor = -1;        // Milnor number; -1 where infinite or beyond the jet
  int corank = 0;         // 2 - rank of the Hessian
  int ak_index = 0;       // k of A_k (corank 1), else 0
  int real_branches = -1; // number of real branches for A_k and ordinary points; -1 if not decided here
  bool crossing = false;  // branches cross (bifurcation point) rather than touch (rotation-index.md)
  std::vector<TangentLine> tangent_cone;  // real lines of the lowest form
  int complex_lines = 0;  // non-real roots of the lowest form (with multiplicity)
  double real_form = 0;   // c * lambda of §4.4 for corank 1 (sign decides real branches for odd k)
};

/// Classifies the germ of h at (0, 0). h(0,0) and grad h(0,0) are taken as zero when below the
/// zero tolerance; otherwise the point is kRegular.
Classification classify(const LocalJet& h, const ClassifyOptions& options = {});

/// Milnor number of the germ (exact rank computation on the truncated jet); -1 if it does not
/// stabilise within the jet's order. `rows` receives dim Q/(J + M^N) for N = 1, 2, ...
int milnor_number(const LocalJet& h, double rank_tolerance = 1e-9, std::vector<int>* rows = nullptr);

/// The splitting-lemma reduction of a corank-1 germ: phi(Y) = h(X(Y), Y) with h_X(X(Y), Y) = 0,
/// in the eigen-coordinates (X, Y) of the Hessian; lambda = h_XX(0).
struct SplittingLemma {
  Eigen::Matrix2d axes;  // columns: X direction, Y direction (unit) in (s, t)
  double lambda = 0;
  Taylor<kLocalOrder> x_of_y;  // X(Y)
  Taylor<kLocalOrder> phi;     // h(X(Y), Y)
};
SplittingLemma splitting_lemma(const LocalJet& h);
/// The elimination step of the splitting lemma for a jet g already in its axes (g_XX(0) != 0):
/// X(Y) solving g_X(X(Y), Y) = 0 and phi(Y) = g(X(Y), Y); `axes` is left unset.
SplittingLemma eliminate_first_variable(const LocalJet& g);

}  // namespace ssimarch
