// The rotation-index condition of loop closure (thesis ch. 6 sec. 6.3; spec rotation-index.md §4
// item 3), kept incrementally along one march from the tangents the tracer computes anyway.
//
// The thesis closes a loop when proximity, first-order and index conditions hold together. The
// index condition compares the accumulated signed turning of the tangent in the parameter plane
// (u, v) of the parametric surface, sum theta, with 2 pi I_p for the candidate indices of the
// curve traced so far. A march of our tracer stops at every located singular point
// (MarchLimits::watch_crossings), so between its start and its return it is a regular arc of the
// intersection, which does not cross itself in space, nor in the chart (u, v) of a surface the
// chart parametrises one-to-one. Such a closed curve is simple, and its index is known before it
// closes (thesis Prop. 2.4; on a periodic chart, docs/math/closure_turning.md):
//   - |I| = 1 when the curve closes in the unwrapped plane (a contractible loop),
//   - I = 0 when it comes back shifted by a period (it winds round a cylinder, a torus, a pole).
// These are the thesis' candidates |I| +- 1 with the estimate I = 0 of a curve that has met no
// bifurcation point, made exact by the period shift. A return near the start with any other
// turning (half a turn, none, two turns) is not the loop closing: another strand of the curve
// passing by (a near miss), and the march goes on.
//
// The turning is unknown (the condition then does not apply, and closure rests on proximity and
// first order, march/loop_closure.cpp) where the chart cannot tell it: implicit-implicit pairs
// (no parameter plane), a step whose tangent in the plane turns by more than
// kRotationMaxChordTurn (the image folds, next to a pole), a zero tangent in the plane, a march
// that went through a pole (another chart) or passed a crossing of branches unwatched (the arc is
// no longer simple; the thesis then needs the loop decomposition of its sec. 6.3).
#pragma once

#include <array>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

/// Largest turn (radians) of the tangent in the plane of the rotation index (thesis sec. 2.1)
/// between successive points or chords of a regular stretch: a larger one means the curve's
/// image in that plane folds there (its tangent in the plane nearly vanishes, e.g. next to a
/// pole of the parametrisation), so the turning is not determined by the points (an atan2 in
/// (-pi, pi] cannot tell a turn of 3 rad from one of -3.28). Cusps at singular points (a turn
/// near pi) are corners of a piecewise regular curve (Def. 2), allowed there by
/// network/rotation_index.cpp. About 115 degrees: well above the tracer's max_turn_angle
/// (0.6 rad in space), well below pi.
inline constexpr double kRotationMaxChordTurn = 2.0;  // rad

/// The index condition of thesis ch. 6 (sec. 6.3, sigma): the accumulated turning must be
/// within this of 2 pi times the expected index (rad). The thesis' runs use 0.5; candidates
/// differ by 2 pi, so sigma may be large.
inline constexpr double kRotationIndexSigma = 0.5;  // rad

class ClosureTurning {
 public:
  /// No plane: the condition never applies (implicit-implicit pairs).
  ClosureTurning() = default;
  /// Starts at the march's first point, whose tangent in the plane (u', v') is t0; periods of
  /// u and v (0 when not periodic).
  ClosureTurning(const Vec2& t0, const Vec2& periods);

  /// One accepted step: the tangent in the plane at the new point and the step's displacement
  /// in the plane (periodic parameters reduced to half a period, Problem::difference).
  void step(const Vec2& t, const Vec2& displacement);
  /// The turning can no longer be told (a pole passed, a crossing passed unwatched).
  void lose() { known_ = false; }

  bool known() const { return known_; }
  /// Signed turning (rad) from the start's tangent to the current point's.
  double turning() const { return turning_; }
  /// Whole periods the march has shifted by in u and v.
  std::array<long, 2> period_shift() const;

  /// The index condition for closing at the start from the current point: the turning of the
  /// whole loop (the accumulated turning plus the turn from the current tangent back to t0) is
  /// within kRotationIndexSigma of 2 pi I for the expected I (+-1 for a loop closed in the
  /// plane, 0 for one shifted by a period). True when the turning is not known.
  bool admits_closure() const;

 private:
  bool known_ = false;
  Vec2 t0_ = Vec2::Zero(), t_ = Vec2::Zero(), periods_ = Vec2::Zero(), shift_ = Vec2::Zero();
  double turning_ = 0;
};

/// Signed angle (rad, atan2 in (-pi, pi]) from a to b in the plane.
double signed_turn(const Vec2& a, const Vec2& b);

}  // namespace ssimarch
