// The one entry point that analyses a singular point of an intersection curve (docs/singular.md):
// locate it (Newton on h = 0, grad h = 0 over the local curve, singular/locate.hpp), build the
// local algebraic curve there (thesis ch. 5 §5.2.3; singular/local_curve.hpp), classify its germ
// (thesis §5.2.5; singular/classify.hpp) and find its half-branches with their Puiseux expansions
// (singular/half_branches.hpp). Every caller (the tracer's registry of singular points, a start on
// a singular point, the hunt of uncertain regions, the geometry of a branch at a singular point,
// `ssimarch singular`) goes through here, so the four steps are assembled in one place.
#pragma once

#include <string_view>
#include <vector>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/half_branches.hpp"
#include "ssimarch/singular/local_curve.hpp"
#include "ssimarch/singular/locate.hpp"

namespace ssimarch {

/// How far the analysis got; each value states where it stopped.
enum class SingularAnalysisStatus {
  kAnalysed,      // located (or taken as given), local curve built, classified
  kNotLocated,    // the location did not converge to a point where the surfaces meet with parallel
                  // normals (location.status says why); nothing else was computed
  kNoLocalCurve,  // the local curve could not be built at the located point (curve.status says why)
};
/// "analysed", "not_located", "no_local_curve".
std::string_view to_string(SingularAnalysisStatus s);

struct SingularAnalysisOptions {
  /// Locate the singular point nearest to the given unknowns first; off: the given point is the
  /// point (a location made before, or a point whose local curve alone is wanted).
  bool locate = true;
  /// Find the half-branches (the costliest step: a circle of sign samples and a corrected exit
  /// point per half-branch); off where only the type decides what follows (with_half_branches
  /// adds them later).
  bool half_branches = true;
  LocateOptions locate_options;
  HalfBranchOptions half_branch_options;
};

/// A singular point analysed: where, its local curve, its class and its half-branches.
struct SingularAnalysis {
  SingularAnalysisStatus status = SingularAnalysisStatus::kNotLocated;
  SingularLocation location;         // location.x: the unknowns (not wrapped into the domain)
  LocalCurve curve;                  // valid when status is kAnalysed
  Classification kind;               // valid when status is kAnalysed
  std::vector<HalfBranch> branches;  // empty unless asked for and status is kAnalysed

  bool analysed() const { return status == SingularAnalysisStatus::kAnalysed; }
};

/// Analyses the singular point at (options.locate: nearest to) the unknowns x.
SingularAnalysis analyse_singular_point(const Problem& problem, const VecX& x,
                                        const SingularAnalysisOptions& options = {});

/// Analyses a point located before (its status is not checked again: a caller that located it
/// decided to keep it); location.x is where the local curve is built.
SingularAnalysis analyse_singular_point(const Problem& problem, const SingularLocation& located,
                                        const SingularAnalysisOptions& options = {});

/// The radius (model units) around an analysed singular point within which the curve's own points
/// have normals parallel to within kLocateSineTolerance, so that a location started there may stop
/// short of the point and be accepted (docs/math/singular_local_curve.md §2): on a branch
/// Y ~ X^((k+1)/2) of an A_k germ in germ units |grad h| ~ 2 |X|^((k+1)/2), at a point of
/// multiplicity m >= 3 it is ~ |X|^(m-1). Two singular points this close cannot be told apart by
/// their locations: the more degenerate is the point (7e-4 germ lengths at a tacnode, whose valley
/// held points located as cusps or nodes of their own: Ex. 18). 0 where not analysed or mu < 1.
double resolution_radius(const SingularAnalysis& a);

/// Adds the half-branches to an analysis made without them (nothing when not analysed or present).
void with_half_branches(const Problem& problem, SingularAnalysis* analysis, const HalfBranchOptions& options = {});

}  // namespace ssimarch
