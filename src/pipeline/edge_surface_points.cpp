// Points of a face's boundary on another surface (pipeline/edge_surface_points.hpp). The signed
// distance g(s) = sign(n . r) |r|, r = c(s) - F(u*, v*) with (u*, v*) the surface's nearest point,
// changes by at most the arc length between two boundary points (the distance to a set is
// 1-Lipschitz), which is what lets a piece be discarded without sampling inside it.
#include "ssimarch/pipeline/edge_surface_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch {

namespace {

// Initial pieces per boundary curve before the Lipschitz test splits them: only the cost depends
// on it (a piece that may hold a root is split anyway); 16 keeps a full circle's pieces under a
// quarter turn, where the chord-based length bound below is good to 1 %.
constexpr int kInitialPieces = 16;
// Chords through a piece's middle underestimate its arc length by less than this factor for a
// piece turning by up to a half turn (pi / 2 / sqrt(2) = 1.11 per half).
constexpr double kArcOverChords = 1.25;

// g at p and the parameters of the surface's nearest point (to continue from on a nearby point).
struct Distance {
  double g = std::numeric_limits<double>::quiet_NaN();
  Vec2 uv = Vec2::Zero();
};

class SignedDistance {
 public:
  explicit SignedDistance(const Surface& s) : s_(s) {}

  // From the nearest of a grid of the domain when guess is null, else continued from guess.
  Distance at(const Vec3& p, const Vec2* guess) const {
    Distance out;
    if (!s_.is_parametric()) {
      const Vec3 grad = gradient(s_, p);
      const double f = s_.value(Vec3T<double>(p)), norm = grad.norm();
      if (norm > 0) out.g = f / norm;
      return out;
    }
    std::optional<Vec2> uv =
        guess ? std::optional<Vec2>(refine_closest_parameters(s_, p, *guess)) : closest_parameters(s_, p);
    if (!uv) return out;
    out.uv = *uv;
    const Vec3 r = p - point(s_, (*uv)[0], (*uv)[1]);
    const std::optional<Vec3> n = unit_normal(s_, (*uv)[0], (*uv)[1]);
    out.g = n && r.dot(*n) < 0 ? -r.norm() : r.norm();
    return out;
  }

 private:
  const Surface& s_;
};

struct Sample {
  double s = 0;
  Vec3 p = Vec3::Zero();
  Distance d;
};

class BoundaryCurveSearch {
 public:
  BoundaryCurveSearch(const FaceRegion& region, int curve, const SignedDistance& g, const Box& surface_box,
                      const EdgeSurfaceTolerances& tol, std::vector<Vec3>* out)
      : region_(region), curve_(curve), g_(g), surface_box_(surface_box), tol_(tol), out_(out) {}

  void run() {
    const auto [lo, hi] = region_.boundary_range(curve_);
    std::vector<Vec3> at;
    for (int k = 0; k <= kInitialPieces; ++k)
      at.push_back(region_.boundary_point(curve_, lo + (hi - lo) * k / kInitialPieces));
    if (apart(at)) return;
    std::vector<Sample> samples;
    for (int k = 0; k <= kInitialPieces; ++k) {
      const double s = lo + (hi - lo) * k / kInitialPieces;
      samples.push_back({s, at[static_cast<std::size_t>(k)], g_.at(at[static_cast<std::size_t>(k)], nullptr)});
      if (std::abs(samples.back().d.g) <= tol_.on_surface) out_->push_back(samples.back().p);
    }
    for (int k = 0; k < kInitialPieces; ++k)
      piece(samples[static_cast<std::size_t>(k)], samples[static_cast<std::size_t>(k) + 1]);
  }

 private:
  // Continued from a nearby sample's foot point; where that breaks the Lipschitz bound against the
  // sample (Gauss-Newton found another stationary point of the distance, e.g. the far side of a
  // thin cylinder the boundary passes through), from the nearest point of a grid instead.
  Sample sample(double s, const Sample& near) const {
    const Vec3 p = region_.boundary_point(curve_, s);
    Distance d = g_.at(p, &near.d.uv);
    const double bound = std::abs(near.d.g) + (p - near.p).norm();
    if (!(std::abs(d.g) <= bound + tol_.on_surface)) {
      const Distance global = g_.at(p, nullptr);
      if (std::abs(global.g) < std::abs(d.g) || !std::isfinite(d.g)) d = global;
    }
    return {s, p, d};
  }
  // Whether the curve stays out of the surface's box: its points' box grown by the longest chord
  // (each piece lies within kArcOverChords / 2 chords of its ends) misses the box grown by the band.
  bool apart(const std::vector<Vec3>& at) const {
    double chord = 0;
    Vec3 lo = at.front(), hi = at.front();
    for (std::size_t k = 0; k < at.size(); ++k) {
      lo = lo.cwiseMin(at[k]);
      hi = hi.cwiseMax(at[k]);
      if (k > 0) chord = std::max(chord, (at[k] - at[k - 1]).norm());
    }
    const Box& b = surface_box_;
    const double grow = kArcOverChords * chord + tol_.band;
    return lo.x() - grow > b.x.hi || hi.x() + grow < b.x.lo || lo.y() - grow > b.y.hi || hi.y() + grow < b.y.lo ||
           lo.z() - grow > b.z.hi || hi.z() + grow < b.z.lo;
  }
  const Sample& nearer(const Sample& a, const Sample& b) const { return std::abs(a.d.g) <= std::abs(b.d.g) ? a : b; }

  // Recursion depth is bounded by log2(curve length / band): a piece is split only while longer.
  void piece(const Sample& a, const Sample& b) {
    if (!std::isfinite(a.d.g) || !std::isfinite(b.d.g)) return;
    if ((a.d.g < 0) != (b.d.g < 0)) return root(a, b);
    const Vec3 mid_point = region_.boundary_point(curve_, 0.5 * (a.s + b.s));
    const double length = kArcOverChords * ((mid_point - a.p).norm() + (b.p - mid_point).norm());
    if (length <= tol_.band || std::abs(a.d.g) + std::abs(b.d.g) > length) return;
    const Sample m = sample(0.5 * (a.s + b.s), nearer(a, b));
    if (std::abs(m.d.g) <= tol_.on_surface) out_->push_back(m.p);
    const double band = tol_.band;
    if (std::abs(a.d.g) <= band && std::abs(m.d.g) <= band && std::abs(b.d.g) <= band) return;  // runs along
    piece(a, m);
    piece(m, b);
  }

  // The root of g between a and b (a sign change): Illinois steps, a bisection whenever two
  // steps did not halve the bracket, until |g| <= on_surface or the bracket is one ulp wide. A
  // sign change with |g| above the band at its end is a jump of the nearest point (the
  // surface's domain edge), not a root.
  void root(Sample a, Sample b) {
    double ga = a.d.g, gb = b.d.g;
    Sample best = nearer(a, b);
    double width = std::abs(b.s - a.s);
    for (int step = 0; std::abs(best.d.g) > tol_.on_surface; ++step) {
      const bool bisect = step % 2 == 1 && std::abs(b.s - a.s) > 0.5 * width;
      if (step % 2 == 1) width = std::abs(b.s - a.s);
      double s = bisect ? 0.5 * (a.s + b.s) : b.s - gb * (b.s - a.s) / (gb - ga);
      s = std::clamp(s, std::min(a.s, b.s), std::max(a.s, b.s));
      if (s == a.s || s == b.s) break;  // one ulp
      const Sample m = sample(s, nearer(a, b));
      if (!std::isfinite(m.d.g)) return;
      if (std::abs(m.d.g) < std::abs(best.d.g)) best = m;
      if ((m.d.g < 0) == (gb < 0)) {
        ga /= 2;  // Illinois: the end kept twice has its value halved
      } else {
        a = b;
        ga = gb;
      }
      b = m;
      gb = m.d.g;
    }
    if (std::abs(best.d.g) <= tol_.band) out_->push_back(best.p);
  }

  const FaceRegion& region_;
  int curve_;
  const SignedDistance& g_;
  const Box& surface_box_;
  EdgeSurfaceTolerances tol_;
  std::vector<Vec3>* out_;
};

}  // namespace

std::vector<Vec3> edge_surface_points(const FaceRegion& region, const Surface& surface,
                                      const EdgeSurfaceTolerances& tolerances) {
  const SignedDistance g(surface);
  std::vector<Vec3> found;
  for (int i = 0; i < region.boundary_curves(); ++i)
    BoundaryCurveSearch(region, i, g, surface.box(), tolerances, &found).run();
  std::vector<Vec3> out;  // one point per cluster closer than the band
  for (const Vec3& p : found)
    if (std::none_of(out.begin(), out.end(), [&](const Vec3& q) { return (p - q).norm() <= tolerances.band; }))
      out.push_back(p);
  return out;
}

}  // namespace ssimarch
