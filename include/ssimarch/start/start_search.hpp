// How the start points of a problem were found and what the search guarantees (docs/topology.md,
// "Certified start points"): the record the start stage hands to the trace and to the output.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

/// How the start points were found; JSON `start_points.method` is to_string of it.
enum class StartSearchMethod {
  kSampling,        // "sampling": samples of the domain corrected onto the curve (start/start_points.hpp)
  kCertified,       // "certified": the interval search (start/certified_start_points.hpp)
  kGiven,           // "given": the scene's or the caller's start points
  kClosedForm,      // "closed-form": no search; the curves are exact (analytic/closed_form.hpp)
  kDisjointBoxes,   // "box": no search; the surfaces' boxes do not overlap (Problem::disjoint)
  kCoincident,      // "coincident": no search; the surfaces share a region (pipeline/coincidence.hpp)
  kSharedBoundary,  // "shared-boundary": no search; faces of one solid, which meet only along their shared
                    // edges and at their shared vertices (pipeline/shared_boundary.hpp)
};
std::string_view to_string(StartSearchMethod m);

/// Why the certified search left a box undecided; JSON `uncertain_regions[].reason`.
enum class UncertainReason {
  kBudgetSpent,            // "budget spent": the box budget ran out before the box was decided
  kSingularOrNonIsolated,  // "singular or non-isolated root": no test can decide the box at this size
};
std::string_view to_string(UncertainReason r);

/// A box of the unknowns in which the certified start-point search decided nothing: it may hold
/// a start point that was not found (docs/topology.md).
struct UncertainRegion {
  std::vector<Interval> box;  // one interval per unknown of H
  std::string system;         // the square system searched, e.g. "boundary u = 0", "turning du = 0"
  UncertainReason reason = UncertainReason::kSingularOrNonIsolated;
};

/// How the start points were found, and what is guaranteed (docs/topology.md).
struct StartPointSearch {
  StartSearchMethod method = StartSearchMethod::kSampling;
  bool certified = false;  // every branch in the domain has a start point (every box decided)
  long boxes = 0;          // boxes examined by the certified search
  double time_ms = 0;
  std::vector<UncertainRegion> uncertain_regions;
  std::string note;  // why sampling was used, or what the certificate does not cover
};

}  // namespace ssimarch
