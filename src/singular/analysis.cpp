#include "ssimarch/singular/analysis.hpp"

#include <cmath>

namespace ssimarch {

std::string_view to_string(SingularAnalysisStatus s) {
  switch (s) {
    case SingularAnalysisStatus::kAnalysed: return "analysed";
    case SingularAnalysisStatus::kNotLocated: return "not_located";
    case SingularAnalysisStatus::kNoLocalCurve: return "no_local_curve";
  }
  return "not_located";
}

SingularAnalysis analyse_singular_point(const Problem& problem, const VecX& x, const SingularAnalysisOptions& options) {
  if (!options.locate) {
    SingularLocation given;
    given.status = LocateStatus::kConverged;
    given.x = x;
    given.point = problem.point(x);
    return analyse_singular_point(problem, given, options);
  }
  const SingularLocation located = locate_singular_point(problem, x, options.locate_options);
  if (located.status != LocateStatus::kConverged) {
    SingularAnalysis a;
    a.location = located;
    return a;
  }
  return analyse_singular_point(problem, located, options);
}

SingularAnalysis analyse_singular_point(const Problem& problem, const SingularLocation& located,
                                        const SingularAnalysisOptions& options) {
  SingularAnalysis a;
  a.location = located;
  a.curve = local_curve(problem, located.x);
  if (a.curve.status != LocalCurveStatus::kOk) {
    a.status = SingularAnalysisStatus::kNoLocalCurve;
    return a;
  }
  a.kind = classify(a.curve.h, {.length = a.curve.germ_length});
  a.status = SingularAnalysisStatus::kAnalysed;
  if (options.half_branches) a.branches = half_branches(problem, a.curve, a.kind, options.half_branch_options);
  return a;
}

double resolution_radius(const SingularAnalysis& a) {
  if (!a.analysed() || a.kind.milnor < 1) return 0;
  const double sine = kLocateSineTolerance;
  const double fraction = a.kind.multiplicity >= 3 ? std::pow(sine, 1.0 / (a.kind.multiplicity - 1))
                                                   : std::pow(0.5 * sine, 2.0 / (a.kind.milnor + 1));
  return fraction * a.curve.germ_length;
}

void with_half_branches(const Problem& problem, SingularAnalysis* analysis, const HalfBranchOptions& options) {
  if (!analysis->analysed() || !analysis->branches.empty()) return;
  analysis->branches = half_branches(problem, analysis->curve, analysis->kind, options);
}

}  // namespace ssimarch
