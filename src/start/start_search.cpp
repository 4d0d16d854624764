#include "ssimarch/start/start_search.hpp"

namespace ssimarch {

std::string_view to_string(StartSearchMethod m) {
  switch (m) {
    case StartSearchMethod::kSampling: return "sampling";
    case StartSearchMethod::kCertified: return "certified";
    case StartSearchMethod::kGiven: return "given";
    case StartSearchMethod::kClosedForm: return "closed-form";
    case StartSearchMethod::kDisjointBoxes: return "box";
    case StartSearchMethod::kCoincident: return "coincident";
    case StartSearchMethod::kSharedBoundary: return "shared-boundary";
  }
  return "sampling";
}

std::string_view to_string(UncertainReason r) {
  switch (r) {
    case UncertainReason::kBudgetSpent: return "budget spent";
    case UncertainReason::kSingularOrNonIsolated: return "singular or non-isolated root";
  }
  return "singular or non-isolated root";
}

}  // namespace ssimarch
