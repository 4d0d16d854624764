// Detecting singular points along a trace, as pure functions of two consecutive points (thesis
// ch. 5 §5.2.1 and Fig. 5.3; rotation-index §6.5), and hunting isolated singular points that no
// trace passes near (issue 10, "Isolated points").
//
// The oriented tangent field T(x) = D point(x) * v(x), where v is the generalised cross product
// of the rows of J_H (the signed (n-1)-minors; for implicit-implicit pairs v = grad f x grad g,
// the thesis' N_F x N_G), is continuous along the curve and vanishes exactly at its singular
// points. Along one branch it keeps its orientation between regular points; stepping over a
// crossing (a node, a triple point) reverses it relative to the branch (Fig. 5.3), so
// T(a) . T(b) < 0 between consecutive points a, b means "a crossing was stepped over: go back
// and locate". Together with sin theta = |N_F x N_G| < 0.01 (thesis ch. 5 §5.2.1) and the rank ratio.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/locate.hpp"

namespace ssimarch {

struct DetectionThresholds {
  double sine = 0.01;        // sin theta below which a point is near-singular (thesis ch. 5 §5.2.1)
  double rank_ratio = 1e-3;  // Problem::rank_ratio below which J_H is near rank-deficient
};

/// The oriented, unnormalised tangent T(x) of the curve of `problem` at x (3D; zero at a singular
/// point). Its length is the product of the row norms of J_H times sin theta (scale-dependent).
Vec3 oriented_tangent(const Problem& problem, const VecX& x);

struct StepSignals {
  double sine_a = 0, sine_b = 0;  // |N_F x N_G| at a and b
  double rank_a = 0, rank_b = 0;  // Problem::rank_ratio at a and b
  double tangent_cos = 1;         // cosine of the angle between T(a) and T(b)
  bool flipped = false;           // tangent_cos < 0: the orientation reversed (a crossing stepped over)
  bool near_singular = false;     // a sine or rank ratio below its threshold
  bool suspect() const { return flipped || near_singular; }
};

/// The detection signals between two consecutive traced points a and b (unknowns).
StepSignals step_signals(const Problem& problem, const VecX& a, const VecX& b, const DetectionThresholds& thresholds = {});

struct HuntOptions {
  int grid = 32;                 // samples per parameter direction
  LocateOptions locate;          // options of each location
  double merge_distance = 1e-7;  // solutions closer than this (unknowns) are the same point
  // Only starts where sin(theta) = |N_F x N_G| is at most this (a singular point has sin theta = 0
  // and it grows about linearly with the distance); infinity: every start near the curve.
  double max_sine = std::numeric_limits<double>::infinity();
  // Boxes of the unknowns to hunt in (one Interval per unknown), each sampled with region_grid
  // points per direction; empty: the whole domain with `grid`. The certified start-point search's
  // uncertain regions hold every singular point (a singular root of the turning systems is
  // never certified; docs/math/tangential_contact.md §4).
  std::vector<std::vector<Interval>> regions;
  int region_grid = 5;
  // Starts whose Newton target (3D) this returns true for are not located: points already
  // explained (a traced curve of tangential contact, a known singular point).
  std::function<bool(const Vec3&)> skip;
  // Starts of the whole domain's grid for which this returns false are not tried (their cells are
  // known to hold no singular point); empty: every start.
  std::function<bool(const VecX&)> consider;
  // Starts x0 for which this returns true, given the grid step per unknown of the box being
  // sampled, are not tried: x0's cell provably holds no singular point (an interval test,
  // start/patch_exclusion.hpp); empty: every start.
  std::function<bool(const VecX& x0, const VecX& step)> holds_none;
  // Called with each new singular point as soon as it is found (before the next start), so that
  // `skip` can account for what the caller derived from it.
  std::function<void(const SingularLocation&)> on_found;
};

/// Every singular point of the problem found from a grid: over the first surface's domain (with
/// the second surface's nearest parameters for parametric-parametric pairs), or over the 3D box
/// (grid/2 per direction) for implicit-implicit pairs. At each start the local curve h is built
/// and the start kept when Newton's step towards a critical point of h stays within one grid
/// cell; each kept start is located by locate_singular_point (h = h_s = h_t = 0). Isolated
/// points (Ex. 16) included. A start whose Newton target lies within a tenth of a cell of where
/// an earlier location ended (singular or a near miss) is not located again. Throws InputError for grid < 3.
std::vector<SingularLocation> hunt_singular_points(const Problem& problem, const HuntOptions& options = {});

/// The singular points of the curve at the poles of the problem's parametric surfaces (degenerate
/// edges, problem/poles_and_trims.hpp: a cone's apex, a sphere's pole) that lie on the other
/// surface: at such a point the parametrisation itself is singular, so neither a grid nor an
/// interval search over the parameters sees it as an ordinary critical point; each is located
/// from the pole (the local curve over a regular chart, local_curve.hpp). An isolated point where
/// a cone's apex touches a sphere's pole (OpenCASCADE bug21494_2) is one. Points where the curve
/// passes a pole regularly are not returned.
std::vector<SingularLocation> singular_points_at_poles(const Problem& problem, const LocateOptions& options = {});

}  // namespace ssimarch
