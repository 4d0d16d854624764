#include "ssimarch/march/step_rule.hpp"

#include <cmath>

namespace ssimarch {

StepReport make_step_report(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, const Vec3& predicted, double h,
                            int iterations) {
  StepReport r;
  r.h = h;
  r.chord = (p1 - p0).norm();
  r.turn = std::atan2(t0.cross(t1).norm(), t0.dot(t1));
  r.correction = (p1 - predicted).norm();
  r.sagitta = 0.5 * r.chord * std::tan(r.turn / 4);
  r.iterations = iterations;
  return r;
}

double clamp_step(double L, const StepBounds& b) {
  if (!(L == L)) return b.max_step;
  return std::clamp(L, b.min_rule, b.max_step);
}

}  // namespace ssimarch
