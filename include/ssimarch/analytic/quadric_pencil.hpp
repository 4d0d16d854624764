// The real ruled members of the pencil of two quadrics (docs/math/closed_form_quadrics.md, "The
// pencil"). Levin's observation (J. Z. Levin, "A parametric algorithm for drawing pictures of
// solid objects composed of quadric surfaces", CACM 19(10), 1976; "Mathematical models for
// determining the intersections of quadric surfaces", CGIP 11, 1979): every member
// Q(lambda) = A - lambda B of the pencil passes through the curve A = B = 0, and A meets any member
// other than itself in that same curve. A member is degenerate where det(A - lambda B) = 0 (a
// quartic in lambda); a real root whose member has rank 3 and is indefinite on its complement is
// a real cone (vertex finite) or cylinder (vertex at infinity) — Wang, Goldman & Tu ("Enhancing
// Levin's method for computing quadric-surface intersections", CAGD 20, 2003) classify the
// members by this rank and inertia — and its rulings carry the section of A as a quadratic
// (ruled_section.hpp). Two ellipsoids, an ellipsoid and a sphere or paraboloid, ... so reduce to
// "Along the rulings".
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "ssimarch/analytic/ruled_section.hpp"
#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

struct PencilMember {
  double lambda = 0;     // Q = A - lambda B (A, B scaled to unit largest entry)
  bool cylinder = false; // vertex at infinity
  Rulings rulings;       // an ellipse of the member and its vertex: X = E(theta) + t K (homogeneous)
};

/// The real cones and elliptic cylinders of the pencil of A and B, cylinders first (their
/// rulings never pass through a vertex), then cones by increasing distance of the vertex from
/// `centre` (the region's centre; `scale` its size). Empty where there is none: every real root
/// of the quartic gives a member of rank < 3 (pairs of planes), an imaginary cone (only its
/// vertex is real), or a hyperbolic or parabolic cylinder (rulings not parametrised by an ellipse).
std::vector<PencilMember> ruled_members(const Eigen::Matrix4d& A, const Eigen::Matrix4d& B, const Vec3& centre,
                                        double scale);

}  // namespace ssimarch
