// Constant step L (Barnhill, Farin, Jordan & Piper; docs/marching.md): halved after a rejected
// step, doubled back towards L after an accepted one.
#pragma once

#include "ssimarch/march/step_rule.hpp"

namespace ssimarch {

struct ConstantStep {
  StepBounds bounds;
  double h = 0.05;
  int jet_order() const { return 1; }
  double step() const { return h; }
  void start(const CurveGeometry&) { h = bounds.max_step; }
  bool acceptable(const StepReport&) const { return true; }
  void accepted(const StepReport&, const CurveGeometry&) { h = std::min(bounds.max_step, 2 * h); }
  bool rejected(const StepReport*) {
    h *= 0.5;
    return h >= bounds.min_step;
  }
};

}  // namespace ssimarch
