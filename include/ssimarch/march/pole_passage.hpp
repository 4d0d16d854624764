// Passing a curve through a pole of a parametrisation: a degenerate edge of a parametric
// surface that F maps to one point P (surface/degenerate_edges.hpp; the sphere's poles, a
// patch edge whose control points coincide). At P the parameters of that surface give no
// tangent (F_w = 0), yet the curve is regular in 3D: its point is P, its tangent is
// N_F x N_G with N_F the limit normal at the pole, and it leaves P along the meridian w_out
// whose inward direction dF/dn(w_out) is parallel to that tangent. The passage continues the
// march there in a local chart (the curve point beyond P inverted to parameters, then
// corrected), so the curve is one curve through the pole. Derivation and sources:
// docs/math/poles.md (Patrikalakis & Maekawa, Shape Interrogation, §5.8.2; Barnhill & Kersey
// 1990, §4).
#pragma once

#include <optional>
#include <string>

#include "ssimarch/march/result.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

struct PolePassage {
  bool ok = false;        // a regular point beyond the pole was found
  bool through = false;   // the curve passes through the pole point (at_pole is on the curve)
  CurvePoint at_pole;     // through: the pole point, its unknowns and the curve's tangent there
  CurvePoint beyond;      // ok: the curve point past the pole, tangent along the travel
  std::string message;    // why not, for people
};

/// The curve coming from `cur` (unit tangent towards the pole) passes the pole: the point at
/// distance `distance` (model units) beyond it along the curve, corrected to `co.tolerance`.
/// Passes through P when P lies within max(10 tolerance, 1e-12 scale) of the other surface,
/// else goes round it (a near miss) to the mirror of cur across P along the tangent.
PolePassage pass_pole(const Problem& problem, const Pole& pole, const CurvePoint& cur, double distance,
                      const CorrectorOptions& co);

/// A regular curve point about `distance` from x, a curve point on the degenerate edge `pole`
/// (a start point found at a pole): along N_F x N_G at P. Empty when there is none (the curve
/// is tangent to the surface's tangent plane at P, or ends there).
std::optional<CurvePoint> leave_pole(const Problem& problem, const Pole& pole, const UnknownVec& x, double distance,
                                     const CorrectorOptions& co);

/// Unknowns whose 3D point is near q, a point just beyond the pole (|q - P| small): the pole's
/// surface in the chart of the meridian leaving P towards q, the other surface (parametric) by
/// its nearest point; not corrected. For continuations through a pole other than the tracer's
/// (the curves of tangential contact, trace/tangential_contact.hpp).
UnknownVec unknowns_beyond_pole(const Problem& problem, const Pole& pole, const UnknownVec& x, const Vec3& q);

}  // namespace ssimarch
