// The intersection of two surfaces as the zero set of H : R^n -> R^(n-1) (Allgower & Georg,
// Numerical Continuation Methods, ch. 2; docs/architecture.md, "One idea carries the engine"):
//
//   pair kind               unknowns x          H(x)                      n
//   parametric-parametric   (u, v, p, q)        F(u,v) - G(p,q)           4
//   parametric-implicit     (u, v)              g(F(u,v))                 2
//   implicit-implicit       (x, y, z)           (f(x), g(x))              3
//
// A regular point of the curve has rank J_H = n-1; the tangent is J_H's null vector. The 3D
// point of a solution is F(u,v) for the first two kinds and x itself for the third.
//
// Distances: implicit residuals are divided by the gradient norm (|g|/|grad g| is the first-order
// distance to the surface), so every tolerance on H is in model units for all three kinds.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/surface.hpp"
#include "ssimarch/surface/trims.hpp"

namespace ssimarch {

enum class PairKind {
  kParametricParametric,  // x = (u, v, p, q)
  kParametricImplicit,    // x = (u, v) of the first surface; the second is implicit
  kImplicitImplicit,      // x = (x, y, z)
};
std::string_view to_string(PairKind kind);

/// The unknowns of a surface-surface problem (u,v[,p,q] or x,y,z: at most 4) and n x n matrices
/// of them: Eigen keeps them in the object (fixed maximum size), so copying a curve point or a
/// corrector result allocates nothing (issue 12: the marching loop runs per point).
using UnknownVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1>;
using UnknownMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;

/// Storage of the first-order data with the problem's fixed maximum sizes (n <= 4 unknowns,
/// n - 1 <= 3 equations): Eigen keeps them in the object, so linearising allocates nothing
/// (issue 12: the corrector linearises at every iteration of every point).
using EquationVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
using EquationJacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 4>;
using PointJacobian = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 4>;

/// The first-order data of H at one point, all in double.
struct Linearization {
  EquationVec h;              // H(x), n-1 components
  EquationJacobian jacobian;  // dH/dx, (n-1) x n
  Vec3 point;                 // the 3D point of x
  PointJacobian point_jacobian;  // d point / dx, 3 x n
  Vec3 normal_first, normal_second;  // unit surface normals (zero vector where undefined)
  double distance = 0;  // first-order distance of the 3D point from the two surfaces (model units)
};

class Problem {
 public:
  /// For kParametricImplicit, `first` must have a parametric form and `second` an implicit one;
  /// for kParametricParametric both parametric; for kImplicitImplicit both implicit.
  /// Throws InputError otherwise.
  Problem(Surface first, Surface second, PairKind kind);

  PairKind kind() const { return kind_; }
  int dim() const { return dim_; }
  int num_equations() const { return dim_ - 1; }
  const Surface& first() const { return first_; }
  const Surface& second() const { return second_; }

  /// H(x) for any scalar type (double, Jet, Taylor): h has n-1 entries. Implicit residuals
  /// are not normalised here (the normalisation is not polynomial); see Linearization::distance.
  template <class T>
  void residual(const T* x, T* h) const {
    switch (kind_) {
      case PairKind::kParametricParametric: {
        Vec3T<T> a = first_.point(x[0], x[1]);
        Vec3T<T> b = second_.point(x[2], x[3]);
        h[0] = a.x - b.x;
        h[1] = a.y - b.y;
        h[2] = a.z - b.z;
        return;
      }
      case PairKind::kParametricImplicit:
        h[0] = second_.value(first_.point(x[0], x[1]));
        return;
      case PairKind::kImplicitImplicit: {
        Vec3T<T> p(x[0], x[1], x[2]);
        h[0] = first_.value(p);
        h[1] = second_.value(p);
        return;
      }
    }
  }

  /// H(x) as residual() and the 3D point of x as point(), from one call of each surface
  /// (point() alone calls the first surface again): for the curve jets' every order.
  template <class T>
  Vec3T<T> residual_and_point(const T* x, T* h) const {
    switch (kind_) {
      case PairKind::kParametricParametric: {
        Vec3T<T> a = first_.point(x[0], x[1]);
        Vec3T<T> b = second_.point(x[2], x[3]);
        h[0] = a.x - b.x;
        h[1] = a.y - b.y;
        h[2] = a.z - b.z;
        return a;
      }
      case PairKind::kParametricImplicit: {
        Vec3T<T> a = first_.point(x[0], x[1]);
        h[0] = second_.value(a);
        return a;
      }
      case PairKind::kImplicitImplicit: {
        Vec3T<T> p(x[0], x[1], x[2]);
        h[0] = first_.value(p);
        h[1] = second_.value(p);
        return p;
      }
    }
    return {};
  }

  /// The 3D point of x for any scalar type.
  template <class T>
  Vec3T<T> point(const T* x) const {
    if (kind_ == PairKind::kImplicitImplicit) return Vec3T<T>(x[0], x[1], x[2]);
    return first_.point(x[0], x[1]);
  }

  Vec3 point(const UnknownVec& x) const;
  Linearization linearize(const UnknownVec& x) const;
  /// How far J_H is from losing rank, scale-free, in [0, 1]: sigma_min/sigma_max of the
  /// (row-normalised) J_H for 2 or 3 equations; for the single equation of a parametric-implicit
  /// pair |grad g^T DF| / (|grad g| sigma_max(DF)), the sine of the angle between the normals up
  /// to the parameterisation's distortion. 0 at a singular point of the curve.
  static double rank_ratio(const Linearization& L);
  /// The same ratio from the singular values of J_H (decreasing; 2 or 3 equations), for a caller
  /// that has J_H's SVD already.
  static double rank_ratio(const Eigen::Ref<const Eigen::VectorXd>& singular_values);

  // --- the unknowns' domain --------------------------------------------------------------------
  /// Bounds of each unknown: parameter domains (u,v[,p,q]) or the intersection of the implicit
  /// surfaces' boxes (x,y,z).
  const std::vector<Interval>& bounds() const { return bounds_; }
  /// True when the surfaces cannot meet: implicit surfaces whose boxes do not overlap (the
  /// domain is empty), or surfaces of any form whose boxes bound them (primitives, patches: not
  /// expressions) and do not overlap. The intersection is empty; bounds() must not be searched.
  bool disjoint() const { return disjoint_; }
  /// Period of each unknown, 0 where not periodic.
  const std::vector<double>& periods() const { return periods_; }
  /// x with every periodic coordinate moved into [lo, lo + period).
  UnknownVec wrap(const UnknownVec& x) const;
  /// b - a with periodic coordinates reduced to (-period/2, period/2].
  UnknownVec difference(const UnknownVec& a, const UnknownVec& b) const;
  /// Whether x lies in the bounds (periodic ones always do) and in every trim (poles_and_trims.hpp), slack eps.
  bool inside(const UnknownVec& x, double eps = 0.0) const;
  /// Names of the unknowns, e.g. {"u","v","p","q"}.
  std::vector<std::string> unknown_names() const;
  /// A length scale of the problem: the diagonal of the 3D region it lives in.
  double scale() const { return scale_; }

 private:
  Surface first_, second_;
  PairKind kind_;
  int dim_;
  std::vector<Interval> bounds_;
  std::vector<double> periods_;
  double scale_ = 1.0;
  bool disjoint_ = false;
  std::vector<Slab> trims_;  // problem_trims(*this), kept: inside() runs at every step
};

}  // namespace ssimarch
