#include "ssimarch/march/step_control.hpp"

namespace ssimarch {

AnyStepControl make_step_control(const TraceOptions& o) {
  StepBounds b{o.step_length, o.min_step_length, o.min_step};
  switch (o.step) {
    case StepRule::kConstant: return ConstantStep{b, o.step_length};
    case StepRule::kAngular: return AngularStep{b, o.turn_angle, o.step_length};
    case StepRule::kDeviation: return DeviationStep{b, o.deviation, o.step_length};
    case StepRule::kOrder3: return Order3Step{b, o.deviation, o.step_length};
    case StepRule::kChordal: return ChordalStep{b, o.deviation, o.step_length};
  }
  return ConstantStep{b, o.step_length};
}

}  // namespace ssimarch
