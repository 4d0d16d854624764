// Validation and set-up of Bezier patches and B-spline surfaces (evaluation in the headers).
#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/core/error.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/spline_basis.hpp"
#include "ssimarch/surface/spline_limits.hpp"
#include "edge_samples.hpp"

namespace ssimarch {
namespace {

// Checks the net and weights, returns homogeneous points row-major and sets *box.
std::vector<std::array<double, 4>> homogeneous_net(const ControlNet& pts, const WeightNet& w, std::size_t min_u,
                                                    std::size_t min_v, const std::string& where, Box* box) {
  if (pts.size() < min_u)
    throw InputError(where + ".control_points", "needs at least " + std::to_string(min_u) + " rows (along u), got " +
                                                    std::to_string(pts.size()));
  const std::size_t cols = pts[0].size();
  if (cols < min_v)
    throw InputError(where + ".control_points", "needs at least " + std::to_string(min_v) +
                                                    " points per row (along v), got " + std::to_string(cols));
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i].size() != cols)
      throw InputError(where + ".control_points[" + std::to_string(i) + "]",
                       "the net must be rectangular: this row has " + std::to_string(pts[i].size()) +
                           " points, row 0 has " + std::to_string(cols));
  const bool rational = !w.empty();
  if (rational) {
    if (w.size() != pts.size())
      throw InputError(where + ".weights", "must have the shape of the control net: " + std::to_string(pts.size()) +
                                               " rows, got " + std::to_string(w.size()));
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (w[i].size() != cols)
        throw InputError(where + ".weights[" + std::to_string(i) + "]",
                         "must have " + std::to_string(cols) + " entries, got " + std::to_string(w[i].size()));
      for (std::size_t j = 0; j < cols; ++j)
        if (!std::isfinite(w[i][j]) || !(w[i][j] > 0))
          throw InputError(where + ".weights[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                           "weights must be finite and > 0");
    }
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Box b{{kInf, -kInf}, {kInf, -kInf}, {kInf, -kInf}};
  std::vector<std::array<double, 4>> h;
  h.reserve(pts.size() * cols);
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      const Vec3& p = pts[i][j];
      if (!p.allFinite())
        throw InputError(where + ".control_points[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                         "has a non-finite coordinate");
      const double wij = rational ? w[i][j] : 1.0;
      h.push_back({wij * p.x(), wij * p.y(), wij * p.z(), wij});
      b = box_union(b, {{p.x(), p.x()}, {p.y(), p.y()}, {p.z(), p.z()}});
    }
  *box = b;
  return h;
}

void check_knots(const std::vector<double>& k, int degree, int n_ctrl, const std::string& where) {
  const std::size_t expected = static_cast<std::size_t>(n_ctrl + degree + 1);
  if (k.size() != expected)
    throw InputError(where, "needs (control points + degree + 1) = " + std::to_string(expected) + " knots, got " +
                                std::to_string(k.size()));
  for (std::size_t i = 0; i < k.size(); ++i) {
    if (!std::isfinite(k[i])) throw InputError(where + "[" + std::to_string(i) + "]", "knot is not finite");
    if (i > 0 && k[i] < k[i - 1])
      throw InputError(where + "[" + std::to_string(i) + "]", "knots must be non-decreasing");
  }
  const double lo = k[static_cast<std::size_t>(degree)], hi = k[static_cast<std::size_t>(n_ctrl)];
  if (!(lo < hi)) throw InputError(where, "the domain [knot[degree], knot[n]] is empty");
  for (std::size_t i = 0; i < k.size();) {
    std::size_t j = i;
    while (j < k.size() && k[j] == k[i]) ++j;
    const int mult = static_cast<int>(j - i);
    if (mult > degree + 1)
      throw InputError(where + "[" + std::to_string(i) + "]",
                       "knot repeated " + std::to_string(mult) + " times; at most degree + 1 allowed");
    if (k[i] > lo && k[i] < hi && mult > degree)
      throw InputError(where + "[" + std::to_string(i) + "]",
                       "interior knot repeated " + std::to_string(mult) + " times; at most degree allowed");
    i = j;
  }
}

}  // namespace

namespace internal {

int find_span(std::span<const double> knots, int degree, int n_ctrl, double t) {
  // First knot in knots[degree..n_ctrl] above t; the span starts one before it.
  auto first = knots.begin() + degree, last = knots.begin() + n_ctrl + 1;
  int k = static_cast<int>(std::upper_bound(first, last, t) - knots.begin()) - 1;
  k = std::clamp(k, degree, n_ctrl - 1);
  // Validated knots (no multiplicity above degree + 1) make the first and last domain spans
  // non-empty, so clamping always lands on a span of positive length.
  return k;
}

}  // namespace internal

namespace {

// kMaxSplineDegree (surface/spline_limits.hpp) along both directions.
void check_degrees(int u, int v, const std::string& key, const char* what) {
  if (u <= kMaxSplineDegree && v <= kMaxSplineDegree) return;
  throw InputError(key, "degrees (" + std::string(what) + ") must be at most " + std::to_string(kMaxSplineDegree) +
                            " (the largest CAD kernels write, OpenCASCADE's Geom_BSplineSurface::MaxDegree), got [" +
                            std::to_string(u) + ", " + std::to_string(v) + "]");
}

}  // namespace

BezierPatch::BezierPatch(const ControlNet& points, const WeightNet& weights, const std::string& where)
    : rational_(!weights.empty()) {
  homogeneous_ = std::make_shared<const std::vector<std::array<double, 4>>>(
      homogeneous_net(points, weights, 2, 2, where, &box_));
  n_ = static_cast<int>(points.size()) - 1;
  m_ = static_cast<int>(points[0].size()) - 1;
  check_degrees(n_, m_, where + ".control_points", "rows - 1 and points per row - 1");
  domain_ = {{0, 1}, {0, 1}, false, false};
}

BSplineSurface::BSplineSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                               const ControlNet& points, const WeightNet& weights, const std::string& where)
    : p_(degree_u), q_(degree_v), rational_(!weights.empty()) {
  if (degree_u < 1 || degree_v < 1)
    throw InputError(where + ".degree", "degrees must be >= 1, got [" + std::to_string(degree_u) + ", " +
                                            std::to_string(degree_v) + "]");
  check_degrees(degree_u, degree_v, where + ".degree", "[p, q]");
  auto data = std::make_shared<Data>();
  data->homogeneous = homogeneous_net(points, weights, static_cast<std::size_t>(p_) + 1,
                                      static_cast<std::size_t>(q_) + 1, where, &box_);
  nu_ = static_cast<int>(points.size());
  nv_ = static_cast<int>(points[0].size());
  check_knots(knots_u, p_, nu_, where + ".knots_u");
  check_knots(knots_v, q_, nv_, where + ".knots_v");
  domain_ = {{knots_u[static_cast<std::size_t>(p_)], knots_u[static_cast<std::size_t>(nu_)]},
             {knots_v[static_cast<std::size_t>(q_)], knots_v[static_cast<std::size_t>(nv_)]},
             false,
             false};
  data->knots_u = std::move(knots_u);
  data->knots_v = std::move(knots_v);
  data->pieces = internal::extract_bezier_pieces(p_, q_, data->knots_u, data->knots_v, nu_, nv_, data->homogeneous);
  data_ = std::move(data);
  domain_.periodic_u = edges_coincide(0);
  domain_.periodic_v = edges_coincide(1);
  if (data_->pieces)
    kink_ =
        internal::first_kink(*data_->pieces, data_->knots_u, data_->knots_v, domain_.periodic_u, domain_.periodic_v);
}

std::string BSplineSurface::interval_refusal() const {
  if (!data_->pieces)
    return "its Bezier pieces would take more than " + std::to_string(internal::kBezierExtractionBytes >> 20) +
           " MiB (kBezierExtractionBytes)";
  return kink_ ? kink_->describe() : std::string();
}

// closes_seam's sampled test (surface/degenerate_edges.cpp), on the patch itself: the two edges
// across `parameter` agree within kDegenerateEdgeRelative of the control box's diagonal, and they
// are not one point each (a collapsed pair is a pole, not a seam).
bool BSplineSurface::edges_coincide(int parameter) const {
  const double eps = internal::edge_eps(box_);
  double extent = 0;
  const auto at = [this](double u, double v) {
    const Vec3T<double> p = point(u, v);
    return Vec3(p.x, p.y, p.z);
  };
  return internal::edges_agree(at, parameter, domain_, eps, &extent) && extent > eps;
}

}  // namespace ssimarch
