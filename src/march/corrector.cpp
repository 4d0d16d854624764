#include "ssimarch/march/corrector.hpp"

namespace ssimarch {

AnyCorrector make_corrector(const TraceOptions& options) {
  if (options.corrector == CorrectorKind::kProjection) return TangentPlaneProjection{};
  return NewtonCorrector{};
}

CorrectorResult correct(const AnyCorrector& c, const Problem& problem, const UnknownVec& guess, const CorrectorOptions& options) {
  return std::visit([&](const auto& x) { return x.correct(problem, guess, options); }, c);
}

}  // namespace ssimarch
