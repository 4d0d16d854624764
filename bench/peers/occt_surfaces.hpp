// The peer cases' surfaces as OpenCASCADE builds them: analytic Geom_* surfaces (or an exact
// rational B-spline where OpenCASCADE has no analytic class) and exact rational B-spline
// conversions (GeomConvert) of the same surfaces (shared/peers/cases.jsonl, README.md).
#pragma once

#include <string>

#include <Geom_Surface.hxx>

namespace peers {

struct OcctPair {
  Handle(Geom_Surface) first, second;  // null when the case has no such variant
};

/// The analytic variant of the case (cases.jsonl "analytic_variant"); null handles if it has none.
OcctPair occt_analytic(const std::string& name);
/// Both surfaces as (exact, rational where needed) B-splines (cases.jsonl "bspline_s1/s2").
OcctPair occt_bspline(const std::string& name);

}  // namespace peers
