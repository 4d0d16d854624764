// Tensor-product B-spline surface of degrees (p, q), polynomial or rational (NURBS).
//
//   F(u,v) = sum_ij w_ij P_ij N_i^p(u) N_j^q(v) / sum_ij w_ij N_i^p(u) N_j^q(v)
// with knot vectors U (n_u + p + 1 knots) and V (n_v + q + 1 knots), any (clamped or not).
// Domain [U[p], U[n_u]] x [V[q], V[n_v]]. A direction whose two edges are one curve (the seam of
// a closed surface of revolution as CAD writes it: a full circle of rational arcs) is periodic:
// the parameter is reduced into the domain before evaluating, so F(u + width, v) = F(u, v)
// holds as a tracer that wraps across the seam assumes (issue 27: evaluated outside the
// domain, the last span's polynomial continued the circle at another speed, and a curve
// crossing a NURBS sphere's seam drifted off the surface). The knot span is chosen from
// primal(u), primal(v) (style.md 3.4), so a jet at a knot gives the derivatives of the piece to
// the right of it (of the last piece at the domain end). Doubles and jets are evaluated on the
// span's Bezier piece, extracted once (surface/bezier_extraction.hpp), by its Taylor expansion
// in doubles (surface/bezier_piece.hpp; issue 27: order-4 jets through de Boor were 80 % of a
// NURBS trace); interval types (the certified search) are enclosed over their box by the control
// nets of the pieces the box meets, restricted to it (surface/piece_enclosure.hpp, issue 27 item
// 2); other number types, and surfaces too large to extract, by de Boor in homogeneous
// coordinates, first along v on the p + 1 rows active in u, then along u, all in T.
// Control points P[i][j]: i along u (outer index), j along v (inner index). Box: the box of the
// control points (convex hull property, weights > 0).
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/surface/bezier_extraction.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/domain.hpp"
#include "ssimarch/surface/knot_line_continuity.hpp"
#include "ssimarch/surface/piece_enclosure.hpp"
#include "ssimarch/surface/spline_basis.hpp"

namespace ssimarch {

class BSplineSurface {
 public:
  /// Throws InputError (where = `where`) unless: degrees >= 1; the net is rectangular with at
  /// least degree + 1 points each way and finite coordinates; each knot vector is finite,
  /// non-decreasing, of length (points + degree + 1), with a non-empty domain, no knot repeated
  /// more than degree + 1 times and no knot inside the domain more than degree times; weights
  /// (optional) have the net's shape and are finite and > 0.
  BSplineSurface(int degree_u, int degree_v, std::vector<double> knots_u, std::vector<double> knots_v,
                 const ControlNet& points, const WeightNet& weights = {}, const std::string& where = "bspline");

  int degree_u() const { return p_; }
  int degree_v() const { return q_; }
  bool is_rational() const { return rational_; }
  const std::vector<double>& knots_u() const { return data_->knots_u; }
  const std::vector<double>& knots_v() const { return data_->knots_v; }
  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    const T uu = into_period(u, domain_.u, domain_.periodic_u), vv = into_period(v, domain_.v, domain_.periodic_v);
    if constexpr (internal::TaylorEvaluable<T>::value) {
      if (data_->pieces)
        return internal::piece_point(data_->pieces->view(internal::find_span(data_->knots_u, p_, nu_, primal(uu)),
                                                         internal::find_span(data_->knots_v, q_, nv_, primal(vv))),
                                     rational_, uu, vv);
    } else if constexpr (internal::Enclosure<T>::value) {
      if (data_->pieces) {
        const internal::BezierExtraction& x = *data_->pieces;
        return internal::enclose_on_pieces(
            internal::PieceGrid{x.breaks_u, x.breaks_v, x.nets.data(), p_, q_, domain_.periodic_u, domain_.periodic_v},
            rational_, uu, vv);
      }
    }
    return point_de_boor(uu, vv);
  }

  /// Whether interval types get sound enclosures (the certified search may run on this surface):
  /// the pieces were extracted and the surface is C1 across every knot line and closed seam
  /// (surface/knot_line_continuity.hpp). Otherwise interval_refusal() says why.
  bool encloses_on_intervals() const { return data_->pieces.has_value() && !kink_; }
  std::string interval_refusal() const;

  /// F(u, v) by de Boor on the net, in T (no periodic reduction): the evaluation of surfaces
  /// too large to extract, and the reference the Bezier pieces and their enclosures are tested and
  /// timed against (its span is chosen from the midpoint: not an enclosure across a knot line).
  template <class T>
  Vec3T<T> point_de_boor(const T& u, const T& v) const {
    if (rational_) return eval<T, 4>(u, v);
    return eval<T, 3>(u, v);
  }
  /// Whether the Bezier pieces were extracted (false above kBezierExtractionBytes).
  bool has_bezier_pieces() const { return data_->pieces.has_value(); }

 private:
  struct Data {
    std::vector<double> knots_u, knots_v;
    std::vector<std::array<double, 4>> homogeneous;  // row-major, (w x, w y, w z, w)
    std::optional<internal::BezierExtraction> pieces;
  };

  // t moved by a whole number of periods into [lo, hi] (unchanged inside it, and where the
  // direction is not periodic); derivatives of a jet are those at the moved point.
  template <class T>
  static T into_period(const T& t, const Interval& range, bool periodic) {
    const double x = primal(t);
    if (!periodic || (range.lo <= x && x <= range.hi) || !std::isfinite(x)) return t;
    return t - T(std::floor((x - range.lo) / range.width()) * range.width());
  }

  template <class T, std::size_t D>
  Vec3T<T> eval(const T& u, const T& v) const {
    const Data& d = *data_;
    const int ku = internal::find_span(d.knots_u, p_, nu_, primal(u));
    const int kv = internal::find_span(d.knots_v, q_, nv_, primal(v));
    internal::PointScratch<T, D> row(static_cast<std::size_t>(q_) + 1), col(static_cast<std::size_t>(p_) + 1);
    for (int a = 0; a <= p_; ++a) {
      const std::size_t i = static_cast<std::size_t>(ku - p_ + a);
      for (int b = 0; b <= q_; ++b) {
        const std::size_t j = static_cast<std::size_t>(kv - q_ + b);
        for (std::size_t c = 0; c < D; ++c)
          row[static_cast<std::size_t>(b)][c] = T(d.homogeneous[i * static_cast<std::size_t>(nv_) + j][c]);
      }
      internal::de_boor<T, D>(row.span(), d.knots_v, q_, kv, v);
      col[static_cast<std::size_t>(a)] = row[static_cast<std::size_t>(q_)];
    }
    internal::de_boor<T, D>(col.span(), d.knots_u, p_, ku, u);
    const auto& q = col[static_cast<std::size_t>(p_)];
    if constexpr (D == 4) return {q[0] / q[3], q[1] / q[3], q[2] / q[3]};
    else return {q[0], q[1], q[2]};
  }

  bool edges_coincide(int parameter) const;

  int p_ = 0, q_ = 0, nu_ = 0, nv_ = 0;
  bool rational_ = false;
  std::shared_ptr<const Data> data_;
  std::optional<internal::KnotLineKink> kink_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
