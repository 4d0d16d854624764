// The node where two branches of a ruled section cross, reported from the closed form
// (docs/math/closed_form_quadrics.md, "Crossing points from the closed form").
//
// At a double root tau of the discriminant Delta of a t^2 + b t + c on the rulings, with
// Delta''(tau) != 0 (a root of multiplicity exactly 2), the two roots t+- = (-b +- S) / 2a with
// S = (theta - tau) sqrt(Delta / (theta - tau)^2) are two analytic branches through the point,
// with distinct slopes dt/dtheta = (-b' +- sqrt(Delta''/2)) / 2a: an ordinary node (A1) of the
// curve in the ruling coordinates (theta, t), hence in space (the rulings parametrise the
// cylinder or cone regularly away from the apex, which is not on the curve). Their jets in theta
// give the tangents and the Puiseux (here Taylor) expansions of the four half-branches exactly,
// in the frame and form of the general classifier (trace/singular_registry.hpp): no local
// curve, no classification, no circle search.
#pragma once

#include <optional>

#include "ssimarch/analytic/ruled_section.hpp"
#include "ssimarch/trace/result.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// The report of the node at the double root `theta` of Delta (a crossing of RuledSection), for
/// an implicit-implicit `problem` whose curve the ruled section is: type "node" (A1, multiplicity
/// 2, Milnor number 1), the point, and four half-branches with their tangents, Puiseux
/// expansions up to exponent 6 (along n x tangent, n the first surface's unit normal: the frame
/// of singular/local_curve.hpp) and continuations (straight across). `scale` is Delta's
/// (RuledSection::scale). nullopt where the closed form cannot vouch for a node: Delta''(theta) / 2
/// <= kRuledNodeSeparation x scale (a root of multiplicity 4 or more: a tacnode or higher contact,
/// left to the general classifier), a non-finite jet, or a first surface without a tangent plane
/// there. `curves` is left empty.
std::optional<SingularPointReport> ruled_node(const Problem& problem, const RuledCurves& curves, double theta,
                                              double scale);

}  // namespace ssimarch
