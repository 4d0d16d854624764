// Bezier patches and B-spline surfaces against independent references: exact polynomials,
// Bernstein sums, the Cox-de Boor recursion, Bezier = B-spline with Bezier knots, NURBS circles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "testing/matchers.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_vec(const Vec3& a, const Vec3& b, double tol, const std::string& what = {}) {
  EXPECT_THAT(a, testing::IsNear(b, tol)) << what << " got " << a.transpose() << ", expected " << b.transpose();
}

double binom(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}
double bernstein(int n, int i, double t) { return binom(n, i) * std::pow(t, i) * std::pow(1 - t, n - i); }

// Cox-de Boor recursion for N_i^p(t) (Piegl & Tiller eq. 2.5), right-continuous, with the last
// non-empty span closed at the domain end.
double cox_de_boor(const std::vector<double>& U, int i, int p, double t, double end) {
  if (p == 0) {
    const double lo = U[static_cast<std::size_t>(i)], hi = U[static_cast<std::size_t>(i) + 1];
    if (lo <= t && t < hi) return 1;
    return (t == end && hi == end && lo < hi) ? 1 : 0;
  }
  double s = 0;
  const double a = U[static_cast<std::size_t>(i + p)] - U[static_cast<std::size_t>(i)];
  const double b = U[static_cast<std::size_t>(i + p + 1)] - U[static_cast<std::size_t>(i + 1)];
  if (a > 0) s += (t - U[static_cast<std::size_t>(i)]) / a * cox_de_boor(U, i, p - 1, t, end);
  if (b > 0) s += (U[static_cast<std::size_t>(i + p + 1)] - t) / b * cox_de_boor(U, i + 1, p - 1, t, end);
  return s;
}

ControlNet test_net(int nu, int nv) {
  ControlNet p(static_cast<std::size_t>(nu), std::vector<Vec3>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          Vec3(i + 0.3 * std::sin(1.7 * j + i), j - 0.2 * std::cos(2.3 * i - j), std::sin(0.9 * i + 1.3 * j));
  return p;
}
WeightNet test_weights(int nu, int nv) {
  WeightNet w(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) w[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = 1.0 + 0.6 * std::sin(1.1 * i + 0.7 * j);
  return w;
}

TEST(BezierPatch, BilinearIsExact) {
  const Surface s = BezierPatch({{Vec3(0, 0, 0), Vec3(0, 1, 0)}, {Vec3(1, 0, 0), Vec3(1, 1, 1)}});
  EXPECT_EQ(s.type_name(), "bezier");
  for (auto [u, v] : {std::array{0.0, 0.0}, {0.25, 0.75}, {1.0, 0.3}, {0.6, 1.0}}) {
    const auto F = parametric_jet<3>(s, u, v);
    expect_vec(partial(F, 0, 0), Vec3(u, v, u * v), 1e-15);
    expect_vec(partial(F, 1, 0), Vec3(1, 0, v), 1e-15);
    expect_vec(partial(F, 0, 1), Vec3(0, 1, u), 1e-15);
    expect_vec(partial(F, 1, 1), Vec3(0, 0, 1), 1e-15);
    expect_vec(partial(F, 2, 0), Vec3::Zero(), 1e-15);
    expect_vec(partial(F, 2, 1), Vec3::Zero(), 1e-15);
  }
}

TEST(BezierPatch, ReproducesAKnownPolynomialWithAllDerivatives) {
  // x = u (coefficients i/2), y = v (j/3), z = u^2 v^3 (Bernstein coefficients of u^2 and v^3:
  // only the last ones are 1): F = (u, v, u^2 v^3) on degrees (2, 3).
  ControlNet net(3, std::vector<Vec3>(4));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = Vec3(i / 2.0, j / 3.0, (i == 2 && j == 3) ? 1.0 : 0.0);
  const Surface s = BezierPatch(net);
  for (auto [u, v] : {std::array{0.2, 0.9}, {0.7, 0.4}, {1.0, 1.0}}) {
    const auto F = parametric_jet<6>(s, u, v);
    expect_vec(partial(F, 0, 0), Vec3(u, v, u * u * v * v * v), 1e-15);
    EXPECT_NEAR(F[2].derivative({1, 0}), 2 * u * v * v * v, 1e-14);
    EXPECT_NEAR(F[2].derivative({2, 0}), 2 * v * v * v, 1e-14);
    EXPECT_NEAR(F[2].derivative({1, 2}), 12 * u * v, 1e-13);
    EXPECT_NEAR(F[2].derivative({2, 3}), 12, 1e-12);
    EXPECT_NEAR(F[2].derivative({3, 0}), 0, 1e-12);
    EXPECT_NEAR(F[2].derivative({0, 4}), 0, 1e-12);
    EXPECT_NEAR(F[0].derivative({1, 0}), 1, 1e-14);
    EXPECT_NEAR(F[1].derivative({0, 1}), 1, 1e-14);
  }
}

TEST(BezierPatch, EqualsTheBernsteinSumPolynomialAndRational) {
  const int n = 3, m = 4;
  const ControlNet net = test_net(n + 1, m + 1);
  const WeightNet w = test_weights(n + 1, m + 1);
  const Surface poly = BezierPatch(net), rat = BezierPatch(net, w);
  EXPECT_EQ(rat.get_if<BezierPatch>()->degree_u(), n);
  EXPECT_EQ(rat.get_if<BezierPatch>()->degree_v(), m);
  for (auto [u, v] : {std::array{0.0, 0.0}, {0.3, 0.8}, {0.55, 0.1}, {1.0, 0.5}}) {
    Vec3 num = Vec3::Zero(), numw = Vec3::Zero();
    double den = 0;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) {
        const double b = bernstein(n, i, u) * bernstein(m, j, v);
        const double wij = w[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        num += b * net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        numw += wij * b * net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        den += wij * b;
      }
    expect_vec(point(poly, u, v), num, 1e-14);
    expect_vec(point(rat, u, v), numw / den, 1e-14);
  }
  // Corners interpolate; the box holds the net.
  expect_vec(point(rat, 1, 1), net[3][4], 1e-15);
  expect_vec(point(rat, 0, 1), net[0][4], 1e-15);
  for (const auto& row : net)
    for (const Vec3& p : row) EXPECT_TRUE(rat.box().x.contains(p.x()) && rat.box().z.contains(p.z()));
}

TEST(BSplineSurface, WithBezierKnotsEqualsTheBezierPatch) {
  const ControlNet net = test_net(3, 4);
  const WeightNet w = test_weights(3, 4);
  const std::vector<double> U{0, 0, 0, 1, 1, 1}, V{0, 0, 0, 0, 1, 1, 1, 1};
  for (bool rational : {false, true}) {
    const Surface b = rational ? BezierPatch(net, w) : BezierPatch(net);
    const Surface s = rational ? BSplineSurface(2, 3, U, V, net, w) : BSplineSurface(2, 3, U, V, net);
    EXPECT_EQ(s.type_name(), "bspline");
    for (auto [u, v] : {std::array{0.0, 0.0}, {0.3, 0.8}, {0.55, 0.1}, {1.0, 1.0}, {1.0, 0.2}}) {
      const auto Fb = parametric_jet<3>(b, u, v), Fs = parametric_jet<3>(s, u, v);
      for (int a = 0; a <= 3; ++a)
        for (int c = 0; a + c <= 3; ++c) {
          SCOPED_TRACE(::testing::Message() << "derivative (" << a << ", " << c << ") at " << u << ", " << v);
          expect_vec(partial(Fs, a, c), partial(Fb, a, c), 1e-12 * (1 + 10 * (a + c)));
        }
    }
  }
}

TEST(BSplineSurface, EqualsTheCoxDeBoorSum) {
  const int p = 3, q = 2, nu = 7, nv = 5;
  const std::vector<double> U{0, 0, 0, 0, 0.2, 0.5, 0.5, 1, 1, 1, 1}, V{-1, -1, -1, 0, 0.5, 2, 2, 2};
  const ControlNet net = test_net(nu, nv);
  const WeightNet w = test_weights(nu, nv);
  const Surface s = BSplineSurface(p, q, U, V, net, w);
  EXPECT_EQ(s.domain().u.lo, 0);
  EXPECT_EQ(s.domain().u.hi, 1);
  EXPECT_EQ(s.domain().v.lo, -1);
  EXPECT_EQ(s.domain().v.hi, 2);
  for (double u : {0.0, 0.1, 0.2, 0.35, 0.5, 0.77, 1.0})
    for (double v : {-1.0, -0.3, 0.0, 0.5, 1.2, 2.0}) {
      Vec3 num = Vec3::Zero();
      double den = 0;
      for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
          const double b = cox_de_boor(U, i, p, u, 1.0) * cox_de_boor(V, j, q, v, 2.0);
          const double wij = w[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
          num += wij * b * net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
          den += wij * b;
        }
      expect_vec(point(s, u, v), num / den, 1e-14, "at " + std::to_string(u) + ", " + std::to_string(v));
    }
}

TEST(BSplineSurface, NurbsQuarterAndFullCircleCylindersLieOnTheCylinder) {
  const double r = 1.3, h = 2.0, c = std::sqrt(0.5);
  // Quarter circle (degree 2, weights 1, sqrt(1/2), 1) times a line (degree 1).
  const ControlNet quarter = {{Vec3(r, 0, 0), Vec3(r, 0, h)}, {Vec3(r, r, 0), Vec3(r, r, h)}, {Vec3(0, r, 0), Vec3(0, r, h)}};
  const WeightNet wq = {{1, 1}, {c, c}, {1, 1}};
  // Full circle: 9 points on the square, knots at quarters doubled.
  const Vec3 sq[9] = {{r, 0, 0}, {r, r, 0}, {0, r, 0}, {-r, r, 0}, {-r, 0, 0}, {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
  ControlNet full;
  WeightNet wf;
  for (int i = 0; i < 9; ++i) {
    full.push_back({sq[i], sq[i] + Vec3(0, 0, h)});
    const double wi = i % 2 ? c : 1.0;
    wf.push_back({wi, wi});
  }
  const Surface surfaces[] = {
      BSplineSurface(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, quarter, wq),
      BezierPatch(quarter, wq),
      BSplineSurface(2, 1, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, {0, 0, 1, 1}, full, wf)};
  const Surface cylinder = Cylinder(Vec3::Zero(), Vec3::UnitZ(), r, {0, h});
  for (const Surface& s : surfaces)
    for (double u = 0; u <= 1.0; u += 1.0 / 16)
      for (double v : {0.0, 0.4, 1.0}) {
        const Vec3 p = point(s, u, v);
        EXPECT_NEAR(std::hypot(p.x(), p.y()), r, 1e-14) << s.type_name() << " at " << u;
        EXPECT_NEAR(p.z(), v * h, 1e-14);
        // Its normal is radial (outward: Fu turns counter-clockwise, Fv is +z).
        if (u > 0 && u < 1) {
          const auto n = unit_normal(s, u, v);
          ASSERT_TRUE(n);
          expect_vec(*n, *unit_normal(cylinder, p), 1e-13);
        }
      }
}

// Issue 27: a patch whose two u edges are one curve (the full circle of rational arcs) is periodic
// in u and evaluates beyond its domain at the reduced parameter, jets included: F(u - 1) = F(u)
// and its derivatives (the last span's polynomial continued would move along the circle at
// another speed); the quarter circle, open, is not periodic and extrapolates as before.
TEST(BSplineSurface, AClosedSeamIsPeriodicJetsIncluded) {
  const double r = 1.3, c = std::sqrt(0.5);
  const Vec3 sq[9] = {{r, 0, 0},   {r, r, 0},  {0, r, 0},  {-r, r, 0}, {-r, 0, 0},
                      {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
  ControlNet full;
  WeightNet wf;
  for (int i = 0; i < 9; ++i) {
    full.push_back({sq[i], sq[i] + Vec3(0, 0, 2)});
    wf.push_back({i % 2 ? c : 1.0, i % 2 ? c : 1.0});
  }
  const BSplineSurface closed(2, 1, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, {0, 0, 1, 1}, full, wf);
  EXPECT_TRUE(closed.domain().periodic_u);
  EXPECT_FALSE(closed.domain().periodic_v);
  using J = Jet<2, 3>;
  for (double u : {-0.3, -0.01, 1.01, 1.7, 2.4}) {
    const double reduced = u - std::floor(u);
    const Vec3T<J> a = closed.point(J::variable(0, u), J::variable(1, 0.4));
    const Vec3T<J> b = closed.point(J::variable(0, reduced), J::variable(1, 0.4));
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < J::kSize; ++i) EXPECT_NEAR(a[k][i], b[k][i], 1e-12) << "u = " << u << ", coefficient " << i;
    const Vec3 p(a.x.value(), a.y.value(), a.z.value());
    EXPECT_NEAR(std::hypot(p.x(), p.y()), r, 1e-14) << "u = " << u;
  }
  const ControlNet quarter = {
      {Vec3(r, 0, 0), Vec3(r, 0, 1)}, {Vec3(r, r, 0), Vec3(r, r, 1)}, {Vec3(0, r, 0), Vec3(0, r, 1)}};
  const BSplineSurface open(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, quarter, {{1, 1}, {c, c}, {1, 1}});
  EXPECT_FALSE(open.domain().periodic_u);
}

TEST(BSplineSurface, RejectsInvalidInput) {
  const ControlNet net = test_net(4, 3);
  const std::vector<double> U{0, 0, 0, 0.5, 1, 1, 1}, V{0, 0, 0, 1, 1, 1};
  EXPECT_NO_THROW(BSplineSurface(2, 2, U, V, net));
  auto expect_error = [](auto make, const std::string& where) {
    try {
      make();
      ADD_FAILURE() << "no error for " << where;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), where) << e.what();
    }
  };
  expect_error([&] { return BSplineSurface(2, 2, {0, 0, 0, 0.5, 1, 1}, V, net); }, "bspline.knots_u");
  expect_error([&] { return BSplineSurface(2, 2, {0, 0, 0, 0.7, 0.5, 1, 1}, V, net); }, "bspline.knots_u[4]");
  expect_error([&] { return BSplineSurface(2, 2, U, {0, 0, 0, 0, 1, 1}, net); }, "bspline.knots_v");  // empty domain
  expect_error([&] { return BSplineSurface(2, 2, {0, 0, 0, 0, 1, 1, 1}, V, net); }, "bspline.knots_u[0]");
  expect_error([&] { return BSplineSurface(2, 2, {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, V, test_net(6, 3)); },
               "bspline.knots_u[3]");  // interior multiplicity 3 > degree
  expect_error([&] { return BSplineSurface(2, 2, {0, 1, 1, 1, 1, 1, 1}, V, net); }, "bspline.knots_u");
  expect_error([&] { return BSplineSurface(2, 2, {0, 0, 0, NAN, 1, 1, 1}, V, net); }, "bspline.knots_u[3]");
  expect_error([&] { return BSplineSurface(0, 2, U, V, net); }, "bspline.degree");
  expect_error([&] { return BSplineSurface(3, 2, {0, 0, 0, 0, 1, 1, 1}, V, test_net(3, 3)); }, "bspline.control_points");
  ControlNet ragged = net;
  ragged[2].pop_back();
  expect_error([&] { return BSplineSurface(2, 2, U, V, ragged); }, "bspline.control_points[2]");
  WeightNet w(4, std::vector<double>(3, 1.0));
  w[1][2] = 0;
  expect_error([&] { return BSplineSurface(2, 2, U, V, net, w); }, "bspline.weights[1][2]");
  expect_error([&] { return BSplineSurface(2, 2, U, V, net, WeightNet(3, std::vector<double>(3, 1.0))); }, "bspline.weights");
  ControlNet bad = net;
  bad[0][1].y() = INFINITY;
  expect_error([&] { return BSplineSurface(2, 2, U, V, bad); }, "bspline.control_points[0][1]");
  expect_error([&] { return BezierPatch({{Vec3::Zero(), Vec3::Zero()}}); }, "bezier.control_points");
  expect_error([&] { return BezierPatch({{Vec3::Zero()}, {Vec3::Zero()}}); }, "bezier.control_points");
}

// Issue 29 item 4: degrees beyond kMaxSplineDegree (25, OpenCASCADE's largest) are refused by
// key, before any work; degree 25 itself is a surface.
TEST(SplineSurfaces, DegreesAreBoundedByTheLargestCadKernelsWrite) {
  auto where_of = [](auto make) {
    try {
      make();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("at most 25"), std::string::npos) << e.what();
      return e.where();
    }
    return std::string("no error");
  };
  EXPECT_EQ(where_of([] { return BezierPatch(test_net(27, 3)); }), "bezier.control_points");
  EXPECT_EQ(where_of([] { return BezierPatch(test_net(3, 27)); }), "bezier.control_points");
  EXPECT_NO_THROW(BezierPatch(test_net(26, 26)));
  std::vector<double> U(27 + 26 + 1, 0.0), V{0, 0, 1, 1};
  for (std::size_t i = 27; i < U.size(); ++i) U[i] = 1;
  EXPECT_EQ(where_of([&] { return BSplineSurface(26, 1, U, V, test_net(27, 2)); }), "bspline.degree");
  U.assign(26 + 25 + 1, 0.0);
  for (std::size_t i = 26; i < U.size(); ++i) U[i] = 1;
  EXPECT_NO_THROW(BSplineSurface(25, 1, U, V, test_net(26, 2)));
}

TEST(SplineBasis, SpanSearchClampsToTheDomain) {
  const std::vector<double> U{0, 0, 0, 0.3, 0.3, 0.7, 1, 1, 1};  // degree 2, 6 points
  EXPECT_EQ(internal::find_span(U, 2, 6, 0.0), 2);
  EXPECT_EQ(internal::find_span(U, 2, 6, -5.0), 2);
  EXPECT_EQ(internal::find_span(U, 2, 6, 0.29), 2);
  EXPECT_EQ(internal::find_span(U, 2, 6, 0.3), 4);
  EXPECT_EQ(internal::find_span(U, 2, 6, 0.7), 5);
  EXPECT_EQ(internal::find_span(U, 2, 6, 1.0), 5);
  EXPECT_EQ(internal::find_span(U, 2, 6, 3.0), 5);
}

}  // namespace
}  // namespace ssimarch
