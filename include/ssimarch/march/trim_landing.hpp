// Moving a curve point found outside a trim of an implicit form (surface/trims.hpp) onto the
// trim's face: start-point searches solve on the box faces and the parameter edges, which lie
// beyond the trims, so a boundary root outside a trim stands for the curve's crossing of the
// trim face nearby (docs/math/poles.md §2).
#pragma once

#include <optional>

#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// x itself when it lies in every trim; else the curve point on the face of the first trim it
/// violates (Newton on [H(x); n . p - b], from x), when that converges inside the domain;
/// else empty.
std::optional<UnknownVec> onto_trims(const Problem& problem, const UnknownVec& x, const CorrectorOptions& co);

}  // namespace ssimarch
