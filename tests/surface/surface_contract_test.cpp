// The surface contract, checked for every surface kind (cases.hpp): exact derivatives (jets)
// against finite differences at orders 1-3, consistency across jet orders and number types,
// implicit o parametric = 0 to every order, unit gradients where promised, agreeing normals,
// and the form/domain API.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "testing/matchers.hpp"
#include "ssimarch/surface/derivatives.hpp"
#include "surface/cases.hpp"

namespace ssimarch {
namespace {

using testing::SurfaceCase;

class SurfaceContract : public ::testing::TestWithParam<SurfaceCase> {
 protected:
  Surface s = GetParam().make();
  // Points on the surface: F(uv) for parametric surfaces, the listed points otherwise.
  std::vector<Vec3> surface_points() const {
    std::vector<Vec3> p = GetParam().xyz;
    if (s.is_parametric())
      for (auto [u, v] : GetParam().uv) p.push_back(point(s, u, v));
    return p;
  }
};

// |a - b| <= tol * max(1, |b|), printing where.
void expect_near_vec(const Vec3& a, const Vec3& b, double tol, const std::string& what) {
  EXPECT_THAT(a, testing::IsNear(b, tol * std::max(1.0, b.norm())))
      << what << "\n  got      " << a.transpose() << "\n  expected " << b.transpose();
}

// Cases with a parametric form, with an implicit form, with both.
class ParametricContract : public SurfaceContract {};
class ImplicitContract : public SurfaceContract {};
class TwoFormContract : public SurfaceContract {};

std::string at(double u, double v) { return "at (u,v) = (" + std::to_string(u) + ", " + std::to_string(v) + ")"; }
std::string at(const Vec3& p) {
  return "at p = (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) + ")";
}

// Central-difference step (parameter units / model units) and tolerances (relative): truncation
// h^2 |f'''| / 6 ~ 1e-10 plus rounding 1e-16 |f| / h ~ 1e-11 for the sizes of these surfaces.
constexpr double kH = 1e-5;
constexpr double kTolFirst = 1e-7;
constexpr double kTolSecond = 1e-6;
constexpr double kTolThird = 1e-5;

TEST_P(SurfaceContract, FormsAndDomain) {
  const SurfaceCase& c = GetParam();
  EXPECT_FALSE(s.type_name().empty());
  EXPECT_EQ(s.is_parametric(), !c.uv.empty());
  if (s.is_parametric()) {
    const ParamDomain& d = s.domain();
    EXPECT_LT(d.u.lo, d.u.hi);
    EXPECT_LT(d.v.lo, d.v.hi);
    for (auto [u, v] : c.uv) EXPECT_TRUE(d.u.contains(u) && d.v.contains(v)) << at(u, v);
    if (d.periodic_u)
      for (double v : {d.v.lo + 0.3 * d.v.width(), d.v.lo + 0.8 * d.v.width()})
        expect_near_vec(point(s, d.u.lo, v), point(s, d.u.hi, v), 1e-13, "periodic in u " + at(d.u.lo, v));
    if (d.periodic_v)
      for (double u : {d.u.lo + 0.3 * d.u.width(), d.u.lo + 0.8 * d.u.width()})
        expect_near_vec(point(s, u, d.v.lo), point(s, u, d.v.hi), 1e-13, "periodic in v " + at(u, d.v.lo));
  } else {
    EXPECT_THROW(s.domain(), std::logic_error);
    EXPECT_THROW(s.point<double>(0.0, 0.0), std::logic_error);
  }
  if (!s.is_implicit()) {
    EXPECT_THROW(s.value<double>(Vec3T<double>(0.0, 0.0, 0.0)), std::logic_error);
  }
  // The box holds the surface (sampled).
  const Box& b = s.box();
  for (const Vec3& p : surface_points()) {
    EXPECT_TRUE(b.x.contains(p.x()) && b.y.contains(p.y()) && b.z.contains(p.z())) << "box misses " << at(p);
  }
}

TEST_P(ParametricContract, ParametricFirstDerivativesMatchCentralDifferences) {
  ASSERT_TRUE(s.is_parametric());
  for (auto [u, v] : GetParam().uv) {
    const auto F = parametric_jet<1>(s, u, v);
    expect_near_vec(partial(F, 0, 0), point(s, u, v), 1e-15, "jet value " + at(u, v));
    expect_near_vec(partial(F, 1, 0), (point(s, u + kH, v) - point(s, u - kH, v)) / (2 * kH), kTolFirst, "Fu " + at(u, v));
    expect_near_vec(partial(F, 0, 1), (point(s, u, v + kH) - point(s, u, v - kH)) / (2 * kH), kTolFirst, "Fv " + at(u, v));
  }
}

TEST_P(ParametricContract, ParametricSecondAndThirdDerivativesMatchDifferencesOfLowerOrders) {
  ASSERT_TRUE(s.is_parametric());
  for (auto [u, v] : GetParam().uv) {
    const auto J2 = parametric_jet<2>(s, u, v);
    const auto J4 = parametric_jet<4>(s, u, v);
    // Central difference of the order-k partials (from a jet of order k) in u and in v.
    auto d1 = [&](int a, int b, int dir) -> Vec3 {
      const double du = dir == 0 ? kH : 0, dv = dir == 1 ? kH : 0;
      return (partial(parametric_jet<1>(s, u + du, v + dv), a, b) - partial(parametric_jet<1>(s, u - du, v - dv), a, b)) /
             (2 * kH);
    };
    auto d2 = [&](int a, int b, int dir) -> Vec3 {
      const double du = dir == 0 ? kH : 0, dv = dir == 1 ? kH : 0;
      return (partial(parametric_jet<2>(s, u + du, v + dv), a, b) - partial(parametric_jet<2>(s, u - du, v - dv), a, b)) /
             (2 * kH);
    };
    expect_near_vec(partial(J2, 2, 0), d1(1, 0, 0), kTolSecond, "Fuu " + at(u, v));
    expect_near_vec(partial(J2, 1, 1), d1(1, 0, 1), kTolSecond, "Fuv = d/dv Fu " + at(u, v));
    expect_near_vec(partial(J2, 1, 1), d1(0, 1, 0), kTolSecond, "Fuv = d/du Fv " + at(u, v));
    expect_near_vec(partial(J2, 0, 2), d1(0, 1, 1), kTolSecond, "Fvv " + at(u, v));
    expect_near_vec(partial(J4, 3, 0), d2(2, 0, 0), kTolThird, "Fuuu " + at(u, v));
    expect_near_vec(partial(J4, 2, 1), d2(2, 0, 1), kTolThird, "Fuuv " + at(u, v));
    expect_near_vec(partial(J4, 1, 2), d2(0, 2, 0), kTolThird, "Fuvv " + at(u, v));
    expect_near_vec(partial(J4, 0, 3), d2(0, 2, 1), kTolThird, "Fvvv " + at(u, v));
    // Orders agree: the order-4 jet's low coefficients equal the order-2 jet's.
    for (auto [a, b] : {std::array{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}})
      expect_near_vec(partial(J4, a, b), partial(J2, a, b), 1e-13, "order 4 vs order 2 " + at(u, v));
  }
}

TEST_P(ParametricContract, ParametricFormRunsOnEveryNumberType) {
  ASSERT_TRUE(s.is_parametric());
  auto [u, v] = GetParam().uv[5];
  const Vec3 p = point(s, u, v);
  using J33 = Jet<3, 3>;
  using T6 = Taylor<6>;
  // Jet<3,3> in (u, v, w): a third, unused variable must have zero derivatives.
  const Vec3T<J33> q = s.point<J33>(J33::variable(0, u), J33::variable(1, v));
  const auto J2 = parametric_jet<3>(s, u, v);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(q[i].value(), p[i], 1e-14);
    EXPECT_NEAR(q[i].derivative({1, 1, 0}), J2[static_cast<std::size_t>(i)].derivative({1, 1}), 1e-12);
    EXPECT_NEAR(q[i].derivative({2, 1, 0}), J2[static_cast<std::size_t>(i)].derivative({2, 1}), 1e-11);
    EXPECT_EQ(q[i].derivative({0, 0, 1}), 0.0);
  }
  // Taylor<6> along the diagonal line (u + t, v + t) against the bivariate jet's directional sums.
  const Vec3T<T6> line = s.point<T6>(T6::variable(0, u), T6::variable(0, v));
  for (int i = 0; i < 3; ++i) {
    const auto& f = J2[static_cast<std::size_t>(i)];
    EXPECT_NEAR(line[i][1], f.coef({1, 0}) + f.coef({0, 1}), 1e-12);
    EXPECT_NEAR(line[i][2], f.coef({2, 0}) + f.coef({1, 1}) + f.coef({0, 2}), 1e-11);
  }
}

TEST_P(ImplicitContract, ImplicitDerivativesMatchDifferences) {
  ASSERT_TRUE(s.is_implicit());
  auto f = [&](const Vec3& p) { return s.value<double>(Vec3T<double>(p)); };
  for (const Vec3& p : surface_points()) {
    const auto J3 = implicit_jet<3>(s, p);
    EXPECT_NEAR(J3.value(), f(p), 1e-14 * std::max(1.0, std::fabs(f(p))));
    const Vec3 g = gradient(s, p);
    const Eigen::Matrix3d H = hessian(s, p);
    for (int i = 0; i < 3; ++i) {
      const Vec3 e = Vec3::Unit(i) * kH;
      EXPECT_NEAR(g[i], (f(p + e) - f(p - e)) / (2 * kH), kTolFirst * std::max(1.0, g.norm())) << "df/dx" << i << at(p);
      const Vec3 dg = (gradient(s, p + e) - gradient(s, p - e)) / (2 * kH);
      expect_near_vec(H.col(i), dg, kTolSecond, "Hessian column " + std::to_string(i) + " " + at(p));
      const Eigen::Matrix3d dH = (hessian(s, p + e) - hessian(s, p - e)) / (2 * kH);
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          std::array<int, 3> a{0, 0, 0};
          ++a[static_cast<std::size_t>(i)];
          ++a[static_cast<std::size_t>(j)];
          ++a[static_cast<std::size_t>(k)];
          EXPECT_NEAR(J3.derivative(a), dH(j, k), kTolThird * std::max(1.0, dH.norm())) << "third derivative " << at(p);
        }
    }
  }
}

TEST_P(TwoFormContract, ImplicitVanishesOnTheParametricFormToEveryOrder) {
  ASSERT_TRUE(s.is_parametric() && s.is_implicit());
  using J = Jet<2, 4>;
  for (auto [u, v] : GetParam().uv) {
    const Vec3 p = point(s, u, v);
    EXPECT_LE(std::fabs(s.value<double>(Vec3T<double>(p))), 1e-12 * std::max(1.0, p.norm())) << at(u, v);
    // f(F(u,v)) = 0 identically, so every Taylor coefficient of the composition vanishes.
    const J fF = s.value<J>(s.point<J>(J::variable(0, u), J::variable(1, v)));
    for (int k = 0; k < J::kSize; ++k) EXPECT_LE(std::fabs(fF[k]), 1e-10) << "coefficient " << k << " " << at(u, v);
  }
}

TEST_P(ImplicitContract, GradientHasUnitLengthWherePromised) {
  ASSERT_TRUE(s.is_implicit());
  if (!GetParam().unit_gradient) return;  // no unit gradient promised (see the type's header)
  for (const Vec3& p : surface_points()) EXPECT_NEAR(gradient(s, p).norm(), 1.0, 1e-12) << at(p);
}

TEST_P(TwoFormContract, NormalsOfBothFormsAgree) {
  ASSERT_TRUE(s.is_parametric() && s.is_implicit());
  for (auto [u, v] : GetParam().uv) {
    const auto np = unit_normal(s, u, v);
    const auto ni = unit_normal(s, point(s, u, v));
    ASSERT_TRUE(np && ni) << at(u, v);
    const double c = np->dot(*ni);
    EXPECT_NEAR(std::fabs(c), 1.0, 1e-12) << at(u, v);
    if (GetParam().normal_sign != 0) {
      EXPECT_GT(c * GetParam().normal_sign, 0) << "orientation " << at(u, v);
    }
    // Fu, Fv are tangent to the implicit surface.
    const auto F = parametric_jet<1>(s, u, v);
    EXPECT_NEAR(ni->dot(partial(F, 1, 0)), 0.0, 1e-12 * std::max(1.0, partial(F, 1, 0).norm()));
    EXPECT_NEAR(ni->dot(partial(F, 0, 1)), 0.0, 1e-12 * std::max(1.0, partial(F, 0, 1).norm()));
  }
}

TEST_P(TwoFormContract, CurvaturesOfBothFormsAgree) {
  ASSERT_TRUE(s.is_parametric() && s.is_implicit());
  for (auto [u, v] : GetParam().uv) {
    const auto ff = fundamental_forms(s, u, v);
    const auto ci = implicit_curvatures(s, point(s, u, v));
    ASSERT_TRUE(ff && ci) << at(u, v);
    const Curvatures cp = curvatures(*ff);
    const double sign = unit_normal(s, u, v)->dot(*unit_normal(s, point(s, u, v))) > 0 ? 1.0 : -1.0;
    EXPECT_NEAR(cp.gaussian, ci->gaussian, 1e-9 * std::max(1.0, std::fabs(ci->gaussian))) << at(u, v);
    EXPECT_NEAR(sign * cp.mean, ci->mean, 1e-9 * std::max(1.0, std::fabs(ci->mean))) << at(u, v);
    // Normal curvature along Fu and along Fu + Fv.
    const auto F = parametric_jet<1>(s, u, v);
    for (auto [a, b] : {std::array{1.0, 0.0}, {1.0, 1.0}, {0.3, -1.0}}) {
      const Vec3 w = a * partial(F, 1, 0) + b * partial(F, 0, 1);
      const auto kn = normal_curvature(s, point(s, u, v), w);
      ASSERT_TRUE(kn) << at(u, v);
      EXPECT_NEAR(sign * normal_curvature(*ff, a, b), *kn, 1e-9 * std::max(1.0, std::fabs(*kn))) << at(u, v);
    }
  }
}

std::vector<SurfaceCase> cases_with(bool parametric, bool implicit) {
  std::vector<SurfaceCase> r;
  for (auto& c : testing::all_surface_cases()) {
    const Surface s = c.make();
    if ((!parametric || s.is_parametric()) && (!implicit || s.is_implicit())) r.push_back(c);
  }
  return r;
}
std::string case_name(const ::testing::TestParamInfo<SurfaceCase>& param_info) { return param_info.param.name; }

INSTANTIATE_TEST_SUITE_P(AllKinds, SurfaceContract, ::testing::ValuesIn(cases_with(false, false)), case_name);
INSTANTIATE_TEST_SUITE_P(AllKinds, ParametricContract, ::testing::ValuesIn(cases_with(true, false)), case_name);
INSTANTIATE_TEST_SUITE_P(AllKinds, ImplicitContract, ::testing::ValuesIn(cases_with(false, true)), case_name);
INSTANTIATE_TEST_SUITE_P(AllKinds, TwoFormContract, ::testing::ValuesIn(cases_with(true, true)), case_name);

}  // namespace
}  // namespace ssimarch
