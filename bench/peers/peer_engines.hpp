// The three engines of the peer benchmark, each timed on the intersection call alone and then
// measured (curves, closed, length, residual on the case's surfaces).
#pragma once

#include "occt_surfaces.hpp"
#include "peer_measure.hpp"
#include "ssimarch/pipeline/scene.hpp"

namespace peers {

/// OpenCASCADE GeomAPI_IntSS(first, second, 1e-7); *ms = its wall time.
Outcome run_occt(const OcctPair& pair, const ssimarch::Surface& a, const ssimarch::Surface& b, double* ms);

/// SISL s1859 (topology, geometric resolution 1e-7) then s1310 (marching each curve to a cubic
/// B-spline) on the B-spline pair; *ms = their wall time, the conversion to SISL excluded.
Outcome run_sisl(const OcctPair& bsplines, const ssimarch::Surface& a, const ssimarch::Surface& b, double* ms);

/// ssimarch's run_intersection on the scene's intersection; *ms = its wall time.
Outcome run_ssimarch(const ssimarch::Scene& scene, const ssimarch::IntersectionSpec& spec, double* ms);

}  // namespace peers
