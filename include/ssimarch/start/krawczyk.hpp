// All roots of a square system g : R^m -> R^m (m <= 4) in a box, certified: branch and bound
// over boxes with interval arithmetic, exclusion of boxes whose image misses 0, and the Krawczyk
// operator (Krawczyk 1969; Moore, Kearfott & Cloud, Introduction to Interval Analysis, 2009,
// §8.2)
//
//   K(X) = m - Y g(m) + (I - Y J(X)) (X - m),   m = mid X,  Y ~ J(m)^-1,  J(X) ⊇ {g'(x): x in X}
//
// Every root in X lies in K(X); so K(X) ∩ X = ∅ proves X root-free, and K(X) ⊂ int X proves that
// X holds exactly one root, to which iterating X <- K(X) ∩ X converges quadratically.
//
// A box is tested inflated by a few percent, so that a root on the face shared by two boxes is
// interior to the inflated box of each (it is then found twice and kept once). A box that is
// neither excluded nor proven after shrinking below `min_width` (relative to the start box) is
// undecided: a root with a singular Jacobian (a tangency, a singular point of the curve) or a
// continuum of roots; so is every box left when the budget of boxes is spent. Undecided boxes are
// returned, never dropped.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/start/gradient.hpp"
#include "ssimarch/start/interval_number.hpp"

namespace ssimarch {

inline constexpr int kMaxSystemDimension = 4;
using IntervalBox = std::vector<IntervalNumber>;
using IntervalGradient = Gradient<IntervalNumber, kMaxSystemDimension>;

/// A square system of `dimension` equations in as many unknowns, evaluated on boxes.
struct SquareSystem {
  int dimension = 0;
  /// g on a box, plain intervals: g[i] encloses {g_i(x) : x in box}.
  std::function<void(const IntervalNumber* x, IntervalNumber* g)> value;
  /// g and its Jacobian on a box (x[i] seeded with derivative e_i): g[i].d[j] encloses dg_i/dx_j.
  std::function<void(const IntervalGradient* x, IntervalGradient* g)> gradient;
  /// Optional: `gradient` with exactly `dimension` derivative slots, used when set for a system
  /// of 2 or 3 unknowns. A nested gradient (the turning systems) costs ~N^2 interval operations
  /// per operation, so N = 4 slots for 2 unknowns did ~1.7 times the work of N = 2.
  std::function<void(const Gradient<IntervalNumber, 2>* x, Gradient<IntervalNumber, 2>* g)> gradient2;
  std::function<void(const Gradient<IntervalNumber, 3>* x, Gradient<IntervalNumber, 3>* g)> gradient3;
  /// Optional: true when the box provably holds no root by a necessary condition other than g's
  /// own enclosure (start/patch_exclusion.hpp); tried first. It must never reject a box
  /// holding a root: only rigorous (interval) tests belong here.
  std::function<bool(const IntervalBox& x)> excluded;
};

/// Sets `gradient` and the sized gradient of `system` (its dimension set) from one generic
/// callable f(const Gradient<IntervalNumber, N>* x, Gradient<IntervalNumber, N>* g).
template <class F>
void set_gradients(SquareSystem* system, F f) {
  system->gradient = [f](const IntervalGradient* x, IntervalGradient* g) { f(x, g); };
  if (system->dimension == 2)
    system->gradient2 = [f](const Gradient<IntervalNumber, 2>* x, Gradient<IntervalNumber, 2>* g) { f(x, g); };
  if (system->dimension == 3)
    system->gradient3 = [f](const Gradient<IntervalNumber, 3>* x, Gradient<IntervalNumber, 3>* g) { f(x, g); };
}

struct RootSearchOptions {
  long max_boxes = 5000;      // boxes examined before the rest is reported undecided
  double min_width = 1e-7;    // relative to the start box: smaller undecided boxes are not split
  double root_width = 1e-12;  // relative width (to max(1, |root|)) of a certified root's enclosure
};

struct CertifiedRoot {
  IntervalBox enclosure;  // holds exactly one root, width about root_width
  IntervalBox unique_in;  // the box in which that root was proven unique
  VecX x;                 // the enclosure's midpoint
};

struct UndecidedBox {
  IntervalBox box;
  bool budget = false;  // left when the budget ran out (else: shrunk below min_width undecided)
};

struct RootSearchResult {
  std::vector<CertifiedRoot> roots;
  std::vector<UndecidedBox> undecided;
  long boxes = 0;  // boxes examined
  bool complete() const { return undecided.empty(); }
};

/// Every root of `system` in `box`, each certified, plus the boxes not decided.
RootSearchResult find_all_roots(const SquareSystem& system, const IntervalBox& box, const RootSearchOptions& options);

/// One Krawczyk step on `box`: K(box) (see above). *ok is false when J(mid) is too close to
/// singular to invert (K is then not formed).
IntervalBox krawczyk(const SquareSystem& system, const IntervalBox& box, bool* ok);

}  // namespace ssimarch
