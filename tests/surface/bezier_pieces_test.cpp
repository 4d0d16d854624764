// Bezier pieces and their Taylor expansion (surface/bezier_extraction.hpp, bezier_piece.hpp)
// against de Boor / de Casteljau run in the jet type itself: the same values and derivatives to
// rounding, for every number type the library evaluates surfaces in, on knot vectors that are
// unclamped, repeated and rational, inside and outside the domain.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "testing/random_spline.hpp"

namespace ssimarch {
namespace {

using testing::random_spline;
using testing::Spline;

// Coefficient-wise comparison relative to the largest coefficient of the same order: jets of
// order 12 have coefficients of 1e6 and more where the low ones are of order 1.
template <class J>
void expect_same_jet(const Vec3T<J>& a, const Vec3T<J>& b, double rel, const std::string& what) {
  for (int k = 0; k < 3; ++k) {
    double scale = 1.0;
    for (int i = 0; i < J::kSize; ++i) scale = std::max(scale, std::abs(b[k][i]));
    for (int i = 0; i < J::kSize; ++i)
      ASSERT_NEAR(a[k][i], b[k][i], rel * scale) << what << ", component " << k << ", coefficient " << i;
  }
}

template <class J>
J general_jet(double x0, double a, double b) {
  // x0 + a t + b t^2 + ... : an argument that is not a seed (a curve substituted in a surface).
  J j(x0);
  for (int i = 1; i < J::kSize; ++i) j[i] = (i % 2 ? a : b) / i;
  return j;
}

TEST(BezierPieces, EqualDeBoorForEveryNumberTypeOnRandomSplines) {
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const bool rational = seed % 2 == 0, clamped = seed % 3 != 0;
    const Spline sp = random_spline(seed, rational, clamped);
    const BSplineSurface s(sp.p, sp.q, sp.U, sp.V, sp.P, sp.W);
    ASSERT_TRUE(s.has_bezier_pieces());
    const auto& d = s.domain();
    std::mt19937 rng(seed + 1000);
    // Inside, at knots, at the ends, and a little outside (the end pieces continued).
    std::vector<double> us{d.u.lo, d.u.hi, d.u.lo - 0.05 * d.u.width(), d.u.hi + 0.05 * d.u.width()};
    std::vector<double> vs{d.v.lo, d.v.hi, d.v.lo - 0.05 * d.v.width(), d.v.hi + 0.05 * d.v.width()};
    for (std::size_t k = static_cast<std::size_t>(sp.p) + 1; k < sp.U.size() - static_cast<std::size_t>(sp.p) - 1; ++k)
      us.push_back(sp.U[k]);
    for (std::size_t k = static_cast<std::size_t>(sp.q) + 1; k < sp.V.size() - static_cast<std::size_t>(sp.q) - 1; ++k)
      vs.push_back(sp.V[k]);
    std::uniform_real_distribution<double> fu(d.u.lo, d.u.hi), fv(d.v.lo, d.v.hi);
    for (int i = 0; i < 6; ++i) {
      us.push_back(fu(rng));
      vs.push_back(fv(rng));
    }
    for (double u : us)
      for (double v : vs) {
        if (s.domain().periodic_u || s.domain().periodic_v) continue;
        const std::string at =
            "seed " + std::to_string(seed) + " at (" + std::to_string(u) + ", " + std::to_string(v) + ")";
        const Vec3T<double> a = s.point(u, v), b = s.point_de_boor(u, v);
        ASSERT_TRUE(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z)) << at;
        // Outside the domain next to an empty end span (a free end's knot repeated), de Boor
        // divides 0 by 0; the pieces continue the end piece.
        if (!std::isfinite(b.x)) continue;
        const double scale = 1.0 + std::abs(b.x) + std::abs(b.y) + std::abs(b.z);
        ASSERT_NEAR(a.x, b.x, 1e-13 * scale) << at;
        ASSERT_NEAR(a.y, b.y, 1e-13 * scale) << at;
        ASSERT_NEAR(a.z, b.z, 1e-13 * scale) << at;
        using J1 = Jet<2, 1>;
        using J4 = Jet<2, 4>;
        using J12 = Jet<2, 12>;
        using T6 = Taylor<6>;
        using G1 = Jet<4, 1>;
        expect_same_jet(s.point(J1::variable(0, u), J1::variable(1, v)),
                        s.point_de_boor(J1::variable(0, u), J1::variable(1, v)), 1e-12, at + " Jet<2,1>");
        expect_same_jet(s.point(J4::variable(0, u), J4::variable(1, v)),
                        s.point_de_boor(J4::variable(0, u), J4::variable(1, v)), 1e-11, at + " Jet<2,4>");
        if (seed % 4 == 0)  // order 12 by de Boor costs milliseconds a point
          expect_same_jet(s.point(J12::variable(0, u), J12::variable(1, v)),
                          s.point_de_boor(J12::variable(0, u), J12::variable(1, v)), 1e-8, at + " Jet<2,12>");
        const T6 tu = general_jet<T6>(u, 0.3, -0.7), tv = general_jet<T6>(v, -0.4, 0.2);
        expect_same_jet(s.point(tu, tv), s.point_de_boor(tu, tv), 1e-10, at + " Taylor<6>");
        const G1 gu = G1::variable(2, u) + 0.5 * G1::variable(0, 0.0), gv = G1::variable(3, v) - G1::variable(1, 0.0);
        expect_same_jet(s.point(gu, gv), s.point_de_boor(gu, gv), 1e-12, at + " Jet<4,1>");
        // Swapped seeds: not the placement path.
        const Vec3T<J4> swapped = s.point(J4::variable(1, u), J4::variable(0, v));
        expect_same_jet(swapped, s.point_de_boor(J4::variable(1, u), J4::variable(0, v)), 1e-11, at + " swapped seeds");
      }
  }
}

TEST(BezierPieces, OnePiecePerNonEmptySpanPairWithTheSpansBreaks) {
  const std::vector<double> U{0, 0, 0, 1, 1, 2.5, 4, 4, 4}, V{-1, -1, 0, 3, 3};
  const ControlNet P(6, std::vector<Vec3>(3, Vec3(1, 2, 3)));
  const auto e =
      internal::extract_bezier_pieces(2, 1, U, V, 6, 3, std::vector<std::array<double, 4>>(18, {1, 2, 3, 1}));
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->breaks_u, (std::vector<double>{0, 1, 2.5, 4}));
  EXPECT_EQ(e->breaks_v, (std::vector<double>{-1, 0, 3}));
  // Spans 2..5 along u: span 3 is empty ([1, 1)) and belongs to the piece before it.
  EXPECT_EQ(e->piece_of_span_u, (std::vector<int>{0, 0, 1, 2}));
  EXPECT_EQ(e->nets.size(), 3u * 2u * 3u * 2u);
  // A constant net stays constant (partition of unity holds on every piece).
  for (const auto& h : e->nets) EXPECT_NEAR(h[0], 1.0, 1e-15);
}

TEST(BezierPieces, AHighDegreePatchEqualsDeCasteljau) {
  // Degree 20 x 17 (far above CAD practice): the expansion's differences stay as accurate as
  // the blends, relative to each order's size.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> c(-1.0, 1.0), w(0.5, 2.0);
  ControlNet P(21, std::vector<Vec3>(18));
  WeightNet W(21, std::vector<double>(18));
  for (auto& row : P)
    for (auto& p : row) p = Vec3(c(rng), c(rng), c(rng));
  for (auto& row : W)
    for (auto& x : row) x = w(rng);
  const BezierPatch s(P, W);
  using J = Jet<2, 4>;
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
    for (double v : {0.0, 0.31, 0.5, 0.94, 1.0}) {
      std::string at = "at u = ";  // appended, not a chain of +: g++ 12 warns (-Wrestrict) on the chain here
      at += std::to_string(u);
      at += ", v = ";
      at += std::to_string(v);
      const Vec3T<double> a = s.point(u, v), b = s.point_de_casteljau(u, v);
      EXPECT_NEAR(a.x, b.x, 1e-12) << at;
      EXPECT_NEAR(a.z, b.z, 1e-12) << at;
      expect_same_jet(s.point(J::variable(0, u), J::variable(1, v)),
                      s.point_de_casteljau(J::variable(0, u), J::variable(1, v)), 1e-10, at);
    }
}

TEST(BezierPieces, ASurfaceOverTheMemoryBoundIsEvaluatedByDeBoor) {
  // A bilinear spline with 1200 x 600 control points: 1199 x 599 pieces of 4 points take 46 MB
  // of pieces plus the rows, over kBezierExtractionBytes / 32 points.
  const int nu = 1200, nv = 600;
  std::vector<double> U(static_cast<std::size_t>(nu + 2)), V(static_cast<std::size_t>(nv + 2));
  for (std::size_t i = 0; i < U.size(); ++i) U[i] = static_cast<double>(std::clamp<std::size_t>(i, 1, nu) - 1);
  for (std::size_t i = 0; i < V.size(); ++i) V[i] = static_cast<double>(std::clamp<std::size_t>(i, 1, nv) - 1);
  ControlNet P(static_cast<std::size_t>(nu), std::vector<Vec3>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = Vec3(i, j, std::sin(0.01 * i * j));
  const BSplineSurface s(1, 1, U, V, P);
  EXPECT_FALSE(s.has_bezier_pieces());
  const Vec3T<double> a = s.point(17.25, 300.5);
  EXPECT_NEAR(a.x, 17.25, 1e-12);
  EXPECT_NEAR(a.y, 300.5, 1e-12);
}

}  // namespace
}  // namespace ssimarch
