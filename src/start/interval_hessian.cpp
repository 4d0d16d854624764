#include "ssimarch/start/interval_hessian.hpp"

#include "ssimarch/start/interval_forms.hpp"

namespace ssimarch {

void interval_second_derivatives(const Problem& P, const IntervalBox& box, IntervalSecond* h) {
  IntervalSecond x[kMaxSystemDimension];
  for (int i = 0; i < P.dim(); ++i) x[i] = IntervalSecond(IntervalGradient(box[static_cast<std::size_t>(i)], i), i);
  P.residual(x, h);
}

}  // namespace ssimarch
