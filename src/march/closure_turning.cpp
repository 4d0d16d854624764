#include "ssimarch/march/closure_turning.hpp"

#include <cmath>

namespace ssimarch {

double signed_turn(const Vec2& a, const Vec2& b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

ClosureTurning::ClosureTurning(const Vec2& t0, const Vec2& periods) : t0_(t0), t_(t0), periods_(periods) {
  known_ = t0.allFinite() && t0.squaredNorm() > 0;
}

void ClosureTurning::step(const Vec2& t, const Vec2& displacement) {
  if (!known_) return;
  // A zero or non-finite tangent in the plane has no direction; a turn above
  // kRotationMaxChordTurn within one step is a fold of the image (closure_turning.hpp),
  // whose sign atan2 cannot tell.
  if (!t.allFinite() || t.squaredNorm() == 0 || !displacement.allFinite()) {
    known_ = false;
    return;
  }
  const double theta = signed_turn(t_, t);
  if (std::abs(theta) > kRotationMaxChordTurn) {
    known_ = false;
    return;
  }
  turning_ += theta;
  shift_ += displacement;
  t_ = t;
}

std::array<long, 2> ClosureTurning::period_shift() const {
  std::array<long, 2> k{0, 0};
  for (int i = 0; i < 2; ++i)
    if (periods_[i] > 0) k[static_cast<std::size_t>(i)] = std::lround(shift_[i] / periods_[i]);
  return k;
}

bool ClosureTurning::admits_closure() const {
  if (!known_) return true;
  // The last partial step, from the current point back to the start, turns the tangent by
  // less than a step does; with it the loop's turning is 2 pi times an integer up to rounding.
  // A larger closing turn (a strand passing by after half a turn, against the start's
  // direction) is no return to the start within a step: the thesis' sum theta is then near
  // pi (2k + 1), never within sigma of a candidate.
  const double closing = signed_turn(t_, t0_);
  if (std::abs(closing) > kRotationMaxChordTurn) return false;
  const double total = turning_ + closing;
  const std::array<long, 2> k = period_shift();
  const double expected = (k[0] == 0 && k[1] == 0) ? 2 * M_PI : 0.0;
  return std::abs(std::abs(total) - expected) < kRotationIndexSigma;
}

}  // namespace ssimarch
