// de Klerk (2003) correlation; see correlation.hpp for the citation and formula.
#include "ssimarch/porosity/correlation.hpp"

#include <cmath>
#include <numbers>

namespace ssimarch {

double de_klerk_porosity(double x, double eps_b) {
  if (x <= 0.637) return 2.14 * x * x - 2.53 * x + 1;
  return eps_b + 0.29 * std::exp(-0.6 * x) * std::cos(2.3 * std::numbers::pi * (x - 0.16)) + 0.15 * std::exp(-0.9 * x);
}

}  // namespace ssimarch
