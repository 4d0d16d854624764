// Step rules: how far the next step goes (spec/marching-directions.md §6 for the adaptive ones).
#pragma once

#include <algorithm>
#include <variant>

#include "ssimarch/march/options.hpp"

namespace ssimarch {

/// Constant step L; halved after a rejected step, doubled back towards L after an accepted one.
struct ConstantStep {
  double nominal = 0.05;  // L (model units)
  double min_step = 1e-8; // give up below this (model units)
  double h = 0.05;

  double step() const { return h; }
  void accepted() { h = std::min(nominal, 2 * h); }
  /// Returns false when the step fell below min_step.
  bool rejected() {
    h *= 0.5;
    return h >= min_step;
  }
};

using AnyStepControl = std::variant<ConstantStep>;

}  // namespace ssimarch
