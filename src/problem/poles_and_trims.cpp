#include "ssimarch/problem/poles_and_trims.hpp"

#include <cmath>

namespace ssimarch {

namespace {
// The degenerate edges of surface s (the `index`-th of the pair), whose parameters are the
// unknowns first, first + 1.
void add_poles(const Surface& s, int index, int first, std::vector<Pole>* out) {
  for (const DegenerateEdge& e : degenerate_edges(s))
    out->push_back({first + e.parameter, first + 1 - e.parameter, index, e.value, e.upper, e.point});
}
}  // namespace

std::vector<Pole> problem_poles(const Problem& P) {
  std::vector<Pole> out;
  if (P.kind() == PairKind::kImplicitImplicit) return out;
  add_poles(P.first(), 0, 0, &out);
  if (P.kind() == PairKind::kParametricParametric) add_poles(P.second(), 1, 2, &out);
  return out;
}

const Pole* pole_at(const std::vector<Pole>& poles, const UnknownVec& x, double eps) {
  for (const Pole& p : poles)
    if (std::fabs(x[p.unknown] - p.value) <= eps) return &p;
  return nullptr;
}

std::vector<Slab> problem_trims(const Problem& P) {
  switch (P.kind()) {
    case PairKind::kParametricParametric: return {};
    case PairKind::kParametricImplicit: return implicit_trims(P.second());
    case PairKind::kImplicitImplicit: {
      std::vector<Slab> t = implicit_trims(P.first());
      for (const Slab& s : implicit_trims(P.second())) t.push_back(s);
      return t;
    }
  }
  return {};
}

}  // namespace ssimarch
