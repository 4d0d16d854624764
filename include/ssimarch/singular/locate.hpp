// Locating a singular point of an intersection curve: a point where the surfaces meet and their
// normals are parallel (thesis ch. 5 §5.2.1, eq 5.1), to full precision also at multiple roots.
//
// Method (docs/math/singular_local_curve.md §3): at the current point build the local curve
// h(s, t) (local_curve.hpp, a degree-10 Taylor polynomial) and solve the augmented system
//   h = 0,  h_s = 0,  h_t = 0
// on the polynomial by Gauss-Newton with column scaling and backtracking; move to the solution
// and expand again. At a node the 3 x 2 Jacobian [grad h; Hess h] has full rank and Gauss-Newton
// converges quadratically; at A_k (k >= 2) it converges linearly with ratio (k-1)/k along the
// kernel direction, which costs only polynomial evaluations; re-expanding removes the truncation
// error (O(distance^11)) so the limit is the rounding floor of h itself. The thesis' Sederberg
// system stopped 3e-3 from a tacnode (thesis Ex. 18; oracle s003.ch5.Ex18/27); this reaches 1e-12 there.
#pragma once

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/local_curve.hpp"

namespace ssimarch {

struct LocateOptions {
  int max_expansions = 40;       // outer iterations (local curves built)
  int max_inner_iterations = 600;  // Gauss-Newton steps on one polynomial
  double trust_radius = 0.1;     // largest move per expansion, as a fraction of Problem::scale(); also
                                 // at most the polynomial's radius of faithfulness (root test)
  double gap_tolerance =
      kLocateGapTolerance;  // model units (times the model size): |h| at a point where the surfaces meet
  double sine_tolerance = kLocateSineTolerance;  // |grad h| = sine of the angle between the normals at a singular point
};

enum class LocateStatus {
  kConverged,    // h = 0 and grad h = 0 within the tolerances: a singular point of the curve
  kNotSingular,  // converged to a critical point of h where the surfaces do not meet (|h| > gap
                 // tolerance: a near miss), or to a point with |grad h| above sine_tolerance
  kFailed,       // the local curve could not be built (degenerate or non-finite surface)
};
std::string_view to_string(LocateStatus s);

struct SingularLocation {
  LocateStatus status = LocateStatus::kFailed;
  VecX x;                     // the unknowns of the problem
  Vec3 point = Vec3::Zero();  // 3D point
  double gap = 0;             // |h(0, 0)|: distance between the surfaces along the normal (model units)
  double sine = 0;            // |grad h(0, 0)|: sine of the angle between the normals
  double last_step = 0;       // length of the last move in the tangent plane (model units)
  int expansions = 0;
};

/// The singular point nearest to `guess` (unknowns of the problem).
SingularLocation locate_singular_point(const Problem& problem, const VecX& guess, const LocateOptions& options = {});

/// Critical point of the polynomial h with value 0 nearest to `start` within `radius`: the
/// Gauss-Newton solve of (h, h_s, h_t) = 0 described above. Returns the point reached.
Vec2 solve_augmented_system(const LocalJet& h, const Vec2& start, double radius, int max_iterations);

}  // namespace ssimarch
