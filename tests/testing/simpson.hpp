// Composite Simpson rule: the tests' independent reference for arc lengths of closed-form curves.
#pragma once

namespace ssimarch::testing {

/// The integral of f over [a, b] by composite Simpson on n (even) intervals: error O(h^4).
template <class F>
double simpson(F f, double a, double b, int n = 2000) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
  return sum * h / 3;
}

}  // namespace ssimarch::testing
