#include "ssimarch/singular/series.hpp"

#include <algorithm>
#include <cmath>

namespace ssimarch::series {

Series product(const Series& a, const Series& b) {
  Series r(a.size(), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != 0.0)
      for (std::size_t j = 0; i + j < r.size() && j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

Series absolute(Series a) {
  for (double& c : a) c = std::fabs(c);
  return a;
}

Series compose(const LocalJet& p, const Series& s, const Series& t, int low, bool majorant) {
  const int order = static_cast<int>(s.size()) - 1;
  const int degree = std::min(kLocalOrder, order / std::max(1, low));
  const Series S = majorant ? absolute(s) : s, T = majorant ? absolute(t) : t;
  std::vector<Series> sp{Series(s.size(), 0.0)}, tp{Series(s.size(), 0.0)};
  sp[0][0] = tp[0][0] = 1.0;
  for (int k = 1; k <= degree; ++k) sp.push_back(product(sp.back(), S)), tp.push_back(product(tp.back(), T));
  Series r(s.size(), 0.0);
  for (int d = 0; d <= degree; ++d)
    for (int j = 0; j <= d; ++j) {
      const double c = majorant ? std::fabs(coef(p, d - j, j)) : coef(p, d - j, j);
      if (c == 0.0) continue;
      const Series m = product(sp[static_cast<std::size_t>(d - j)], tp[static_cast<std::size_t>(j)]);
      for (std::size_t i = 0; i < r.size(); ++i) r[i] += c * m[i];
    }
  return r;
}

Series power(const Series& g, double alpha) {
  Series r(g.size(), 0.0);
  r[0] = std::pow(g[0], alpha);
  for (std::size_t n = 1; n < g.size(); ++n) {
    double acc = 0;
    for (std::size_t k = 1; k <= n; ++k)
      acc += ((alpha + 1) * static_cast<double>(k) - static_cast<double>(n)) * g[k] * r[n - k];
    r[n] = acc / (static_cast<double>(n) * g[0]);
  }
  return r;
}

std::vector<Series> powers(const Series& f) {
  std::vector<Series> p{Series(f.size(), 0.0)};
  p[0][0] = 1.0;
  for (std::size_t k = 1; k < f.size(); ++k) p.push_back(product(p.back(), f));
  return p;
}

Series substitute(const Series& a, const std::vector<Series>& fp) {
  Series r(fp.front().size(), 0.0);
  for (std::size_t k = 0; k < a.size() && k < fp.size(); ++k)
    if (a[k] != 0.0)
      for (std::size_t i = 0; i < r.size(); ++i) r[i] += a[k] * fp[k][i];
  return r;
}

// Each pass of x <- (y - sum_(k >= 2) y_k x^k) / y_1 fixes one more order (the k >= 2 terms of
// order n involve only the orders of x below n).
Series revert(const Series& y) {
  Series x(y.size(), 0.0), higher = y;
  if (y.size() < 2) return x;
  x[1] = 1.0 / y[1];
  higher[0] = higher[1] = 0.0;
  for (std::size_t pass = 2; pass < y.size(); ++pass) {
    const Series h = substitute(higher, powers(x));
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = ((i == 1 ? 1.0 : 0.0) - h[i]) / y[1];
  }
  return x;
}

}  // namespace ssimarch::series
