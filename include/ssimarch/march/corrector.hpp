// The choice of corrector, which pulls a predicted point onto the intersection curve
// (docs/marching.md, "Correctors"): Newton (newton_corrector.hpp) or seed 000's tangent-plane
// projection (tangent_plane_projection.hpp).
#pragma once

#include <variant>

#include "ssimarch/march/newton_corrector.hpp"
#include "ssimarch/march/options.hpp"
#include "ssimarch/march/tangent_plane_projection.hpp"

namespace ssimarch {

using AnyCorrector = std::variant<NewtonCorrector, TangentPlaneProjection>;
AnyCorrector make_corrector(const TraceOptions& options);
CorrectorResult correct(const AnyCorrector& c, const Problem& problem, const UnknownVec& guess, const CorrectorOptions& options);

}  // namespace ssimarch
