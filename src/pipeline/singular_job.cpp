#include "ssimarch/pipeline/singular_job.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "ssimarch/core/error.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/trace/tangential_contact.hpp"
#include "ssimarch/trace/trace_tolerances.hpp"

namespace ssimarch {

namespace {

// The hunt's locations are converged; each is analysed where it was located.
SingularAnalysis analysed_at(const Problem& P, const SingularLocation& s) {
  SingularAnalysisOptions analyse;
  analyse.locate = false;
  return analyse_singular_point(P, s, analyse);
}

void add_new(SingularAnalysis a, double merge, SingularJobResult* r) {
  for (const SingularAnalysis& p : r->points)
    if ((p.location.point - a.location.point).norm() <= merge) return;
  r->points.push_back(std::move(a));
}

// One hunted point into the result. A point of a contact curve is counted, and the crossing of
// that curve near it (within the registry's reach, trace/singular_registry.cpp) is listed instead;
// a node that is a crossing located off it is that crossing (crossing_behind_node), as in the
// trace's registry.
// crossing_near looks `reach` along the curve both ways, so the contact points within half of it
// of one already searched are not searched again (`searched`).
void take(const Problem& P, const SingularLocation& s, std::vector<Vec3>* searched, SingularJobResult* r) {
  const double merge = kSingularMergeDistance * P.scale(), reach = kCrossingSearchReach * P.scale();
  SingularAnalysis a = analysed_at(P, s);
  if (a.analysed() && a.kind.type == SingularType::kTangentialContact) {
    ++r->contact_points;
    for (const Vec3& p : *searched)
      if ((p - a.location.point).norm() <= 0.5 * reach) return;
    searched->push_back(a.location.point);
    if (const std::optional<SingularLocation> c = crossing_near(P, a.location.x, reach)) {
      SingularAnalysis crossing = analysed_at(P, *c);
      if (crossing.analysed() && crossing.kind.type == SingularType::kTangentLineCrossing)
        add_new(std::move(crossing), merge, r);
    }
    return;
  }
  if (std::optional<SingularAnalysis> crossing = crossing_behind_node(P, a, merge)) a = std::move(*crossing);
  add_new(std::move(a), merge, r);
}

}  // namespace

std::vector<SingularJobResult> run_singular_job(const Scene& scene, const SingularJobOptions& options) {
  if (options.grid < 3) throw InputError("--grid", "must be at least 3, got " + std::to_string(options.grid));
  std::vector<SingularJobResult> out;
  for (const IntersectionSpec& spec : scene.intersections) {
    if (!options.only.empty() && spec.name != options.only) continue;
    const Problem problem = scene.problem(spec);
    HuntOptions hunt;
    hunt.grid = options.grid;
    SingularJobResult r{spec.name, {}};
    std::vector<Vec3> searched;
    for (const SingularLocation& s : hunt_singular_points(problem, hunt)) take(problem, s, &searched, &r);
    out.push_back(std::move(r));
  }
  if (out.empty() && !options.only.empty())
    throw InputError("--intersection", "the scene has no intersection \"" + options.only + "\"");
  return out;
}

}  // namespace ssimarch
