// Empirical radial porosity correlation for monodisperse spheres in a cylinder, for comparison plots.
//
// de Klerk, A. (2003). Voidage variation in packed beds at small column to particle diameter ratio.
// AIChE Journal 49(8), 2022-2029. With x = (R - r) / d the distance from the wall in particle
// diameters and eps_b the bulk porosity:
//   eps(x) = 2.14 x^2 - 2.53 x + 1                                               for x <= 0.637
//   eps(x) = eps_b + 0.29 exp(-0.6 x) cos(2.3 pi (x - 0.16)) + 0.15 exp(-0.9 x)  for x >  0.637
// (as commonly cited; the two branches do not meet exactly at x = 0.637).
#pragma once

namespace ssimarch {

/// de Klerk (2003) porosity at distance `x_wall` = (R - r)/d from the wall, bulk porosity eps_b.
double de_klerk_porosity(double x_wall, double eps_bulk);

}  // namespace ssimarch
