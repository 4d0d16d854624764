// What a whole trace returns (trace/trace_all.hpp, and analytic/closed_form.hpp in the same
// form): the curves a march produces (march/result.hpp), the singular and isolated points met or
// hunted, how the start points were found (start/start_search.hpp), the work and the warnings.
#pragma once

#include <string>
#include <vector>

#include "ssimarch/march/result.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/start/start_search.hpp"

namespace ssimarch {

/// A singular point met by the trace (or hunted), as found by singular/ (docs/singular.md).
struct SingularPointReport {
  VecX x;                                      // the unknowns of H
  Vec3 p = Vec3::Zero();                       // the 3D point
  SingularType type = SingularType::kRegular;  // JSON `type`: to_string (singular/classify.hpp)
  std::string ak;                              // "A1", "D4", ...; empty where none applies
  int multiplicity = 0;
  int milnor = -1;  // -1 where infinite or beyond the local jet
  struct HalfBranch {
    Vec3 tangent = Vec3::Zero();  // unit 3D tangent leaving the point
    VecX param_tangent;           // the same in the unknowns (per unit length)
    // Leading term of the offset from the tangent line along `normal`, w = coefficient X^exponent
    // (model units; exponent 0: straight within resolution), measured before the expansion's
    // refinement: the same frame and sign as expansion[0].
    double coefficient = 0, exponent = 0;
    int continuation = -1;  // index of the half-branch that continues this one through the point
    // Puiseux expansion of the offset along `normal` (unit, 3D): w = sum coefficient X^exponent,
    // X >= 0 the distance along the tangent, up to exponent 6 (singular/puiseux.hpp).
    struct Term {
      double exponent = 0, coefficient = 0;
    };
    std::vector<Term> expansion;
    Vec3 normal = Vec3::Zero();
  };
  std::vector<HalfBranch> half_branches;
  std::vector<int> curves;  // indices of the curves through the point
};

struct TraceResult {
  std::vector<TracedCurve> curves;
  std::vector<SingularPointReport> singular_points;  // met by the curves (thesis ch. 5-6)
  std::vector<SingularPointReport> isolated_points;  // no real branch through them (hunted)
  TraceStats stats;
  StartPointSearch start_search;
  std::vector<std::string> warnings;  // e.g. a start point that could not be put on the curve
  int failed_starts = 0;              // given start points that could not be put on the curve
};

}  // namespace ssimarch
