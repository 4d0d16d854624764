// The surfaces' forms on the certified search's interval types, compiled once in
// src/start/interval_forms_*.cpp (explicit instantiation declarations of Surface::point and
// Surface::value, surface.hpp): the search's translation units include this header instead of each
// compiling every surface kind for every interval type they use (issue 29, the demo's build time).
#pragma once

#include "ssimarch/start/gradient.hpp"
#include "ssimarch/start/interval_number.hpp"
#include "ssimarch/surface/surface.hpp"

// IntervalNumber and its first derivatives in 2..4 unknowns.
#define SSIMARCH_INTERVAL_TYPES_1(X) \
  X(IntervalNumber);                 \
  X(Gradient<IntervalNumber, 2>);    \
  X(Gradient<IntervalNumber, 3>);    \
  X(Gradient<IntervalNumber, 4>)
// Second derivatives (the turning-point systems): Gradient<Gradient<IntervalNumber, A>, B>.
#define SSIMARCH_INTERVAL_TYPES_2(X)           \
  X(Gradient<Gradient<IntervalNumber, 2>, 2>); \
  X(Gradient<Gradient<IntervalNumber, 2>, 3>); \
  X(Gradient<Gradient<IntervalNumber, 2>, 4>); \
  X(Gradient<Gradient<IntervalNumber, 3>, 2>); \
  X(Gradient<Gradient<IntervalNumber, 3>, 3>); \
  X(Gradient<Gradient<IntervalNumber, 3>, 4>)
#define SSIMARCH_INTERVAL_TYPES_3(X)           \
  X(Gradient<Gradient<IntervalNumber, 4>, 2>); \
  X(Gradient<Gradient<IntervalNumber, 4>, 3>); \
  X(Gradient<Gradient<IntervalNumber, 4>, 4>)

namespace ssimarch {

#define SSIMARCH_SURFACE_FORMS_EXTERN(...) SSIMARCH_SURFACE_FORMS(extern template, __VA_ARGS__)
SSIMARCH_INTERVAL_TYPES_1(SSIMARCH_SURFACE_FORMS_EXTERN);
SSIMARCH_INTERVAL_TYPES_2(SSIMARCH_SURFACE_FORMS_EXTERN);
SSIMARCH_INTERVAL_TYPES_3(SSIMARCH_SURFACE_FORMS_EXTERN);
#undef SSIMARCH_SURFACE_FORMS_EXTERN

}  // namespace ssimarch
