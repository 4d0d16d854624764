// Tensor-product Bezier patch of degrees (n, m), polynomial or rational, on [0, 1]^2.
//
//   F(u,v) = sum_ij w_ij P_ij B_i^n(u) B_j^m(v) / sum_ij w_ij B_i^n(u) B_j^m(v)
// (all w_ij = 1 without weights). Doubles and jets are evaluated by the patch's Taylor expansion
// in doubles (surface/bezier_piece.hpp, issue 27); interval types by the hull of the control
// net restricted to their box (surface/piece_enclosure.hpp, issue 27 item 2: de Casteljau in the
// interval type widened exponentially with the degree); other number types by de Casteljau in
// homogeneous coordinates, first along v for each of the n + 1 rows, then along u, all in the
// number type T (style.md 3.4).
// Control points P[i][j]: i = 0..n along u (outer index), j = 0..m along v (inner index).
// Not periodic. Box: the box of the control points, which encloses the patch (convex hull
// property, weights > 0).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/bezier_piece.hpp"
#include "ssimarch/surface/domain.hpp"
#include "ssimarch/surface/piece_enclosure.hpp"
#include "ssimarch/surface/spline_basis.hpp"

namespace ssimarch {

using ControlNet = std::vector<std::vector<Vec3>>;
using WeightNet = std::vector<std::vector<double>>;

class BezierPatch {
 public:
  /// Throws InputError (where = `where`) for a net with fewer than 2 x 2 points, ragged rows,
  /// non-finite coordinates, or weights of another shape or not finite and > 0.
  explicit BezierPatch(const ControlNet& points, const WeightNet& weights = {}, const std::string& where = "bezier");

  int degree_u() const { return n_; }
  int degree_v() const { return m_; }
  bool is_rational() const { return rational_; }
  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    if constexpr (internal::TaylorEvaluable<T>::value)
      return internal::piece_point(internal::BezierPieceView{homogeneous_->data(), n_, m_, 0.0, 1.0, 0.0, 1.0},
                                   rational_, u, v);
    else if constexpr (internal::Enclosure<T>::value)
      return internal::enclose_on_pieces(internal::PieceGrid{kUnitBreaks, kUnitBreaks, homogeneous_->data(), n_, m_},
                                         rational_, u, v);
    else
      return point_de_casteljau(u, v);
  }

  /// F(u, v) by de Casteljau in T: the reference the Taylor expansion and the control-net
  /// enclosures are tested against.
  template <class T>
  Vec3T<T> point_de_casteljau(const T& u, const T& v) const {
    if (rational_) return eval<T, 4>(u, v);
    return eval<T, 3>(u, v);
  }

 private:
  template <class T, std::size_t D>
  Vec3T<T> eval(const T& u, const T& v) const {
    const auto& h = *homogeneous_;
    const std::size_t cols = static_cast<std::size_t>(m_) + 1;
    internal::PointScratch<T, D> row(cols), col(static_cast<std::size_t>(n_) + 1);
    for (std::size_t i = 0; i <= static_cast<std::size_t>(n_); ++i) {
      for (std::size_t j = 0; j < cols; ++j)
        for (std::size_t c = 0; c < D; ++c) row[j][c] = T(h[i * cols + j][c]);
      internal::de_casteljau<T, D>(row.span(), v);
      col[i] = row[0];
    }
    internal::de_casteljau<T, D>(col.span(), u);
    const auto& q = col[0];
    if constexpr (D == 4) return {q[0] / q[3], q[1] / q[3], q[2] / q[3]};
    else return {q[0], q[1], q[2]};
  }

  static constexpr std::array<double, 2> kUnitBreaks{0.0, 1.0};
  int n_ = 0, m_ = 0;
  bool rational_ = false;
  std::shared_ptr<const std::vector<std::array<double, 4>>> homogeneous_;  // row-major, (w x, w y, w z, w)
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
