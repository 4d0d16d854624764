// The singular points met while tracing a problem's curves, with their half-branches and which
// of them a curve has already followed (issue 10 "Tracing through"; thesis ch. 6: a curve is a
// branch, every half-branch leaving a singular point is traced exactly once).
#pragma once

#include <optional>
#include <vector>

#include "ssimarch/trace/result.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/analysis.hpp"

namespace ssimarch {

/// A singular point met by the trace: its analysis (singular/analysis.hpp) and which of its
/// half-branches the curves have followed.
struct SingularNode : SingularAnalysis {
  std::vector<bool> used;   // per half-branch: a curve has left or arrived along it
  std::vector<int> curves;  // indices of the curves through the point (sorted, unique)
};

class SingularRegistry {
 public:
  /// Points closer than merge_distance (model units) are one point.
  SingularRegistry(const Problem& problem, double merge_distance) : problem_(problem), merge_(merge_distance) {}

  /// The index of the node at the located singular point s, classified and with its
  /// half-branches when new.
  int add(const SingularLocation& s);

  /// The half-branch of node n along which a curve whose last point before the node is `last`
  /// arrives: the one whose leading term (tangent and offset c X^gamma) passes nearest to it.
  int arriving_half_branch(int n, const CurvePoint& last) const;

  void mark(int n, int half, int curve);
  SingularNode& node(int n) { return nodes_[static_cast<std::size_t>(n)]; }
  double merge_distance() const { return merge_; }
  const std::vector<SingularNode>& nodes() const { return nodes_; }

  /// The reports of the nodes for TraceResult::singular_points.
  std::vector<SingularPointReport> reports() const;

 private:
  /// A node the analysed point n cannot be told apart from (within the resolution radius of the
  /// more degenerate of the two), made n where n is more degenerate and the node is still unused.
  std::optional<int> within_resolution(const SingularNode& n);

  const Problem& problem_;
  double merge_;
  std::vector<SingularNode> nodes_;
};

/// The report of an analysed singular point, with its half-branches when it has them and
/// `with_branches` (an isolated point is reported without).
SingularPointReport make_report(const SingularAnalysis& a, bool with_branches = true);

}  // namespace ssimarch
