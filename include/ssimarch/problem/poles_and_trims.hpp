// The poles and trims of a problem's domain, in its unknowns (docs/math/poles.md): the
// degenerate edges of its parametric surfaces (surface/degenerate_edges.hpp), through which the
// tracer passes curves in a local chart (march/pole_passage.hpp), and the trims of its surfaces
// used in implicit form (surface/trims.hpp), which Problem::inside honours and on whose faces
// the tracer lands exactly.
#pragma once

#include <vector>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/degenerate_edges.hpp"
#include "ssimarch/surface/trims.hpp"

namespace ssimarch {

/// A degenerate edge of a parametric surface of the pair, in the unknowns: where x[unknown] =
/// value the surface is at `point` whatever x[along] is.
struct Pole {
  int unknown = 0;  // the unknown that is constant on the edge
  int along = 1;    // the same surface's other parameter
  int surface = 0;  // 0: the first surface, 1: the second
  double value = 0;
  bool upper = false;  // the edge is the unknown's upper bound (the domain lies below it)
  Vec3 point = Vec3::Zero();
};

/// The degenerate edges of the problem's parametric surfaces (sampled: compute once per use).
std::vector<Pole> problem_poles(const Problem& problem);

/// The pole among `poles` whose edge x lies on (|x[unknown] - value| <= eps), or nullptr.
const Pole* pole_at(const std::vector<Pole>& poles, const UnknownVec& x, double eps);

/// The trims of the surfaces the problem uses in implicit form: every curve point lies in each.
std::vector<Slab> problem_trims(const Problem& problem);

}  // namespace ssimarch
