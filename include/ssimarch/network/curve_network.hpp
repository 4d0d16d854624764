// The curve network of one intersection (issue 11 item 3; thesis ch. 6: a curve is a branch
// walked straight through its singular points): vertices (singular points, isolated points,
// curve ends on the domain boundary, and any other end, which is a failure), edges (the smooth
// arcs between vertices), branches (the output curves as walks over edges, with closed flag and
// rotation index) and components (branches and vertices connected through shared vertices).
// Built from a finished trace; it says where the trace is incomplete (docs/topology.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/trace/result.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/network/rotation_index.hpp"

namespace ssimarch {

enum class VertexKind {
  kSingularPoint,  // a singular point the curves pass through (TraceResult::singular_points)
  kIsolatedPoint,  // a singular point with no real branch (TraceResult::isolated_points)
  kBoundaryEnd,    // an open curve's end on the domain boundary (Termination::kLeftDomain)
  kInteriorEnd,    // an open curve's end anywhere else: a failure of the trace
};
std::string_view to_string(VertexKind kind);

struct NetworkVertex {
  VertexKind kind = VertexKind::kBoundaryEnd;
  Vec3 p = Vec3::Zero();  // the 3D point
  VecX x;                 // the unknowns of H there
  std::string type;       // the singular point's type ("node", "cusp", ...); empty for ends
};

/// A smooth arc of curve `curve` between two vertices (or a whole smooth closed curve, which has
/// none: from = to = -1). Its points are curve.points[first..last]; when last < first the arc
/// runs through the closing point of a closed curve (first..end, then 1..last).
struct NetworkEdge {
  int from = -1, to = -1;  // vertex ids
  int curve = 0;
  std::size_t first = 0, last = 0;
  double length = 0;  // sum of the circular-arc estimates of its segments (model units)
};

struct NetworkBranch {
  int curve = 0;           // index into TraceResult::curves
  std::vector<int> edges;  // in the curve's order
  bool closed = false;
  double length = 0;       // the curve's length
  RotationIndex rotation;  // closed branches only
};

struct NetworkComponent {
  std::vector<int> branches;  // sorted
  std::vector<int> vertices;  // sorted
};

/// Where the network is incomplete: an open curve end away from the boundary.
struct NetworkFailure {
  int curve = 0;
  std::string end;      // "start" or "end"
  std::string reason;   // the end's Termination (to_string)
  std::string message;  // the trace's message for that end
};

struct CurveNetwork {
  std::vector<NetworkVertex> vertices;
  std::vector<NetworkEdge> edges;
  std::vector<NetworkBranch> branches;
  std::vector<NetworkComponent> components;
  std::vector<NetworkFailure> failures;
  bool complete() const { return failures.empty(); }
};

/// The network of a finished trace. A singular point is matched to the curve points lying on it
/// (the tracer makes it an exact point of each curve through it; match distance 1e-9 x the
/// problem's scale, far below the registry's merge distance).
CurveNetwork build_curve_network(const Problem& problem, const TraceResult& result);

}  // namespace ssimarch
