// The 8-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun, Table 25.4): exact for
// polynomials of degree 15. Nodes +-x_k with weights w_k; the arc lengths of conics, curve
// splines and shared edges integrate their speed with it.
#pragma once

#include <array>

namespace ssimarch {

inline constexpr std::array<double, 4> kGaussLegendre8Nodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                                            0.9602898564975363};
inline constexpr std::array<double, 4> kGaussLegendre8Weights{0.3626837833783620, 0.3137066458778873,
                                                              0.2223810344533745, 0.1012285362903763};

}  // namespace ssimarch
