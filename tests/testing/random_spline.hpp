// Random B-spline surfaces for the evaluation tests (style.md 3.12.5): degrees 1-5, knot vectors
// clamped or with free ends, interior runs of equal knots up to the degree (C0 lines), polynomial
// or rational.
#pragma once

#include <random>
#include <vector>

#include "ssimarch/surface/bezier_patch.hpp"

namespace ssimarch::testing {

struct Spline {
  int p, q;
  std::vector<double> U, V;
  ControlNet P;
  WeightNet W;
};

// Knots with interior runs of up to `degree` equal values; clamped: the first and last degree + 1
// equal; unclamped: free ends (every run at most degree long).
inline std::vector<double> knots(std::mt19937& rng, int degree, int n, bool clamped) {
  std::uniform_real_distribution<double> step(0.1, 1.0);
  std::vector<double> k{-0.7};
  int run = 1;
  for (int i = 1; i < n + degree + 1; ++i) {
    bool stay;
    if (clamped && (i <= degree || i > n))
      stay = true;
    else if (i == n || (clamped && i == degree + 1))
      stay = false;
    else
      stay = run < degree && rng() % 4 == 0;
    k.push_back(stay ? k.back() : k.back() + step(rng));
    run = stay ? run + 1 : 1;
  }
  return k;
}

inline Spline random_spline(unsigned seed, bool rational, bool clamped) {
  std::mt19937 rng(seed);
  Spline s;
  s.p = 1 + static_cast<int>(rng() % 5);
  s.q = 1 + static_cast<int>(rng() % 5);
  const int nu = s.p + 1 + static_cast<int>(rng() % 4), nv = s.q + 1 + static_cast<int>(rng() % 4);
  s.U = knots(rng, s.p, nu, clamped);
  s.V = knots(rng, s.q, nv, clamped);
  std::uniform_real_distribution<double> c(-2.0, 2.0), w(0.3, 3.0);
  s.P.assign(static_cast<std::size_t>(nu), std::vector<Vec3>(static_cast<std::size_t>(nv)));
  if (rational) s.W.assign(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      s.P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = Vec3(c(rng), c(rng), c(rng));
      if (rational) s.W[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = w(rng);
    }
  return s;
}

}  // namespace ssimarch::testing
