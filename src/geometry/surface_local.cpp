#include "ssimarch/geometry/surface_local.hpp"

#include "ssimarch/geometry/curve_geometry.hpp"

namespace ssimarch {

namespace {

template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

Vec3 unit_or_nan(const Vec3& v) {
  double n = v.norm();
  return n > 0 && std::isfinite(n) ? Vec3(v / n) : Vec3::Constant(kNaN);
}

}  // namespace

Vec3 local_point(const SurfaceLocal& s) {
  return std::visit([](const auto& d) { return d.p; }, s);
}

Vec3 unit_normal(const SurfaceLocal& s) {
  return std::visit(Overloaded{[](const ParametricLocal& d) { return unit_or_nan(d.fu.cross(d.fv)); },
                               [](const ImplicitLocal& d) { return unit_or_nan(d.grad); }},
                    s);
}

bool is_finite(const SurfaceLocal& s) {
  return std::visit(Overloaded{[](const ParametricLocal& d) {
                                 return d.p.allFinite() && d.fu.allFinite() && d.fv.allFinite() &&
                                        d.fuu.allFinite() && d.fuv.allFinite() && d.fvv.allFinite() &&
                                        d.fuuu.allFinite() && d.fuuv.allFinite() && d.fuvv.allFinite() &&
                                        d.fvvv.allFinite();
                               },
                               [](const ImplicitLocal& d) {
                                 return d.p.allFinite() && std::isfinite(d.value) && d.grad.allFinite() &&
                                        d.hess.allFinite() && d.third[0].allFinite() && d.third[1].allFinite() &&
                                        d.third[2].allFinite();
                               }},
                    s);
}

Vec2 tangent_coordinates(const ParametricLocal& s, const Vec3& a) {
  Eigen::Matrix2d first;
  first << s.fu.dot(s.fu), s.fu.dot(s.fv), s.fu.dot(s.fv), s.fv.dot(s.fv);
  return first.ldlt().solve(Vec2(a.dot(s.fu), a.dot(s.fv)));
}

double second_form(const SurfaceLocal& s, const Vec3& a, const Vec3& b, const Vec3& normal) {
  return std::visit(Overloaded{[&](const ParametricLocal& d) {
                                 Vec2 x = tangent_coordinates(d, a), y = tangent_coordinates(d, b);
                                 double l = d.fuu.dot(normal), m = d.fuv.dot(normal), n = d.fvv.dot(normal);
                                 return l * x[0] * y[0] + m * (x[0] * y[1] + x[1] * y[0]) + n * x[1] * y[1];
                               },
                               [&](const ImplicitLocal& d) { return -a.dot(d.hess * b) / d.grad.dot(normal); }},
                    s);
}

double normal_curvature(const SurfaceLocal& s, const Vec3& t, const Vec3& normal) {
  return second_form(s, t, t, normal);
}

double third_normal(const SurfaceLocal& s, const Vec3& t, const Vec3& c2, const Vec3& normal) {
  return std::visit(
      Overloaded{[&](const ParametricLocal& d) {
                   // Thesis ch. 3 (torsion, transversal): lambda = 3 II((u',v'), (u'',v'')) + III(t,t,t).
                   Vec2 w = tangent_coordinates(d, t);
                   double a = w[0], b = w[1];
                   Eigen::Matrix2d first;
                   first << d.fu.dot(d.fu), d.fu.dot(d.fv), d.fu.dot(d.fv), d.fv.dot(d.fv);
                   Vec2 rhs(c2.dot(d.fu) - d.fuu.dot(d.fu) * a * a - 2 * d.fuv.dot(d.fu) * a * b - d.fvv.dot(d.fu) * b * b,
                            c2.dot(d.fv) - d.fuu.dot(d.fv) * a * a - 2 * d.fuv.dot(d.fv) * a * b - d.fvv.dot(d.fv) * b * b);
                   Vec2 w2 = first.ldlt().solve(rhs);
                   double l = d.fuu.dot(normal), m = d.fuv.dot(normal), n = d.fvv.dot(normal);
                   return 3 * (l * a * w2[0] + m * (w2[0] * b + a * w2[1]) + n * b * w2[1]) + d.fuuu.dot(normal) * a * a * a +
                          3 * d.fuuv.dot(normal) * a * a * b + 3 * d.fuvv.dot(normal) * a * b * b +
                          d.fvvv.dot(normal) * b * b * b;
                 },
                 [&](const ImplicitLocal& d) {
                   // Seed 004 §4, eqs 4.19-4.20.
                   double third = t.dot(d.third_contract(t, t));
                   return -(third + 3 * t.dot(d.hess * c2)) / d.grad.dot(normal);
                 }},
      s);
}

}  // namespace ssimarch
