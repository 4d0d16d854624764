// The section of a quadric by a plane: a planar conic, classified and parameterised in closed form
// (docs/math/closed_form_quadrics.md, "Plane sections").
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "ssimarch/analytic/conic.hpp"
#include "ssimarch/surface/frame.hpp"

namespace ssimarch {

/// The whole section (unclipped: full ellipses, both hyperbola branches, whole lines) of the
/// quadric X^T Q X = 0 by the plane through plane.origin spanned by plane.e0, plane.e1. `scale` is
/// the model's length scale (the shape is judged on coordinates divided by it); `gap_tolerance`
/// (model units, contact_gap_tolerance): the plane touches the quadric (a point, a double
/// line, two lines through a cone's apex) when moving it by at most this along its normal makes
/// it tangent. An empty vector:
/// no real point. nullopt: the plane lies in the quadric, or the quadric restricted to the plane
/// has no quadratic part (not a section this function describes).
std::optional<std::vector<Conic>> plane_section(const Frame& plane, const Eigen::Matrix4d& Q, double scale,
                                                double gap_tolerance);

}  // namespace ssimarch
