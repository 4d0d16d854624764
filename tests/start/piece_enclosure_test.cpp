// Interval enclosures of B-spline and Bezier surfaces from their pieces' control nets
// (surface/piece_enclosure.hpp, issue 27 item 2) and the C1 check across knot lines
// (surface/knot_line_continuity.hpp): every value, first and second derivative sampled in a box
// lies in the enclosures computed for the box, on random splines (rational, repeated knots,
// unclamped), boxes across knot lines, beyond the domain and across a closed seam; the
// enclosures shrink with the box and beat de Casteljau in the interval type on a high degree;
// and a NURBS cylinder of rational quarter arcs is searched with a certificate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/start/gradient.hpp"
#include "ssimarch/start/interval_number.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "testing/nurbs_cylinder.hpp"
#include "testing/random_spline.hpp"

namespace ssimarch {
namespace {

using I = IntervalNumber;
using G = Gradient<I, 2>;
using Second = Gradient<G, 2>;
using J = Jet<2, 2>;

BSplineSurface random_spline(unsigned seed) {
  const testing::Spline s = testing::random_spline(seed, seed % 2 == 0, seed % 3 != 0);
  return BSplineSurface(s.p, s.q, s.U, s.V, s.P, s.W);
}

// x in e, up to `slack` (the sampled values are rounded doubles; the enclosures hold the exact ones).
void expect_in(double x, const I& e, double slack, const std::string& what) {
  EXPECT_TRUE(e.lo() - slack <= x && x <= e.hi() + slack) << what << ": " << x << " not in " << e;
}

// Every sample of F, its gradient and its Hessian in the box [u0, u1] x [v0, v1] lies in the
// enclosures of the three interval types.
template <class S>
void expect_encloses(const S& s, double u0, double u1, double v0, double v1, const std::string& what) {
  const I bu(u0, u1), bv(v0, v1);
  const Vec3T<I> f0 = s.point(bu, bv);
  const Vec3T<G> f1 = s.point(G(bu, 0), G(bv, 1));
  const Vec3T<Second> f2 = s.point(Second(G(bu, 0), 0), Second(G(bv, 1), 1));
  for (int a = 0; a <= 6; ++a)
    for (int b = 0; b <= 6; ++b) {
      const double u = u0 + (u1 - u0) * a / 6.0, v = v0 + (v1 - v0) * b / 6.0;
      const Vec3T<J> j = s.point(J::variable(0, u), J::variable(1, v));
      for (int k = 0; k < 3; ++k) {
        const std::string at =
            what + " at (" + std::to_string(u) + ", " + std::to_string(v) + "), coordinate " + std::to_string(k);
        double scale = 1;
        for (int i = 0; i < J::kSize; ++i) scale = std::max(scale, std::abs(j[k][i]));
        const double slack = 1e-12 * scale;
        expect_in(j[k].value(), f0[k], slack, at + " value");
        expect_in(j[k].value(), f1[k].v, slack, at + " gradient's value");
        expect_in(j[k].value(), f2[k].v.v, slack, at + " nested value");
        for (int i = 0; i < 2; ++i) {
          expect_in(j[k].d(i), f1[k].d[static_cast<std::size_t>(i)], slack, at + " d/dx" + std::to_string(i));
          expect_in(j[k].d(i), f2[k].v.d[static_cast<std::size_t>(i)], slack, at + " nested d/dx" + std::to_string(i));
          for (int l = 0; l < 2; ++l) {
            std::array<int, 2> m{0, 0};
            ++m[static_cast<std::size_t>(i)];
            ++m[static_cast<std::size_t>(l)];
            expect_in(j[k].derivative(m), f2[k].d[static_cast<std::size_t>(l)].d[static_cast<std::size_t>(i)], slack,
                      at + " second derivative " + std::to_string(i) + std::to_string(l));
          }
        }
      }
    }
}

TEST(PieceEnclosure, HoldsEverySampleOnRandomSplinesAndBoxes) {
  for (unsigned seed = 1; seed <= 30; ++seed) {
    const BSplineSurface s = random_spline(seed);
    ASSERT_TRUE(s.has_bezier_pieces());
    const ParamDomain& d = s.domain();
    if (d.periodic_u || d.periodic_v) continue;
    std::mt19937 rng(seed + 77);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // The whole domain, boxes of several sizes across knot lines, boxes reaching beyond the
    // domain (the end pieces continued), and point boxes on knots.
    std::vector<std::array<double, 4>> boxes{{d.u.lo, d.u.hi, d.v.lo, d.v.hi}};
    for (double size : {0.5, 0.1, 0.01, 0.0}) {
      for (int k = 0; k < 4; ++k) {
        const double cu = d.u.lo + unit(rng) * d.u.width(), cv = d.v.lo + unit(rng) * d.v.width();
        boxes.push_back(
            {cu - size * d.u.width(), cu + size * d.u.width(), cv - size * d.v.width(), cv + size * d.v.width()});
      }
    }
    boxes.push_back({d.u.hi - 0.05, d.u.hi + 0.1, d.v.lo - 0.1, d.v.lo + 0.05});
    const std::vector<double>& U = s.knots_u();
    const double knot = U[U.size() / 2];
    boxes.push_back({knot, knot, d.v.lo, d.v.lo});
    boxes.push_back({knot - 1e-9, knot + 1e-9, d.v.lo, d.v.hi});
    for (const auto& b : boxes) expect_encloses(s, b[0], b[1], b[2], b[3], "seed " + std::to_string(seed));
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(PieceEnclosure, ClosedSeamIsWrappedAndArcsAreC1) {
  const BSplineSurface s = testing::quarter_arc_cylinder();
  ASSERT_TRUE(s.domain().periodic_u);
  EXPECT_TRUE(s.encloses_on_intervals()) << s.interval_refusal();
  const double tau = 2 * std::numbers::pi;
  // Across the seam, from either side, and across an interior double knot.
  expect_encloses(s, tau - 0.1, tau + 0.1, 0.2, 0.3, "across the seam");
  expect_encloses(s, -0.1, 0.1, 0.2, 0.3, "across the seam from below");
  expect_encloses(s, 1.5, 1.7, 0.0, 1.0, "across u = pi/2");
  // On the circle x^2 + y^2 = 1: the enclosure of x over u in [-0.1, 0.1] holds cos(0) = 1 and
  // stays near [cos 0.1, 1] (the box's own range), not the whole circle's [-1, 1].
  const Vec3T<I> f = s.point(I(-0.1, 0.1), I(0.5));
  EXPECT_LE(f.x.hi(), 1.0 + 1e-12);
  EXPECT_GT(f.x.lo(), 0.98);
}

TEST(PieceEnclosure, KinkAcrossADoubleKnotIsFoundAndRefused) {
  // Degree 2 in u with a double knot at u = 1 and a corner in the control polygon there: C0 only.
  const ControlNet P{{{0, 0, 0}, {0, 1, 0}},
                     {{1, 0, 0}, {1, 1, 0}},
                     {{2, 0, 1}, {2, 1, 1}},
                     {{3, 0, 0}, {3, 1, 0}},
                     {{4, 0, 0}, {4, 1, 0}}};
  const BSplineSurface kinked(2, 1, {0, 0, 0, 1, 1, 2, 2, 2}, {0, 0, 1, 1}, P);
  EXPECT_FALSE(kinked.encloses_on_intervals());
  EXPECT_NE(kinked.interval_refusal().find("knot line u = 1"), std::string::npos) << kinked.interval_refusal();
  EXPECT_FALSE(evaluates_on_intervals(Surface(kinked)));
  // The same points with the double knot's neighbours collinear through it: C1, accepted.
  const ControlNet Q{{{0, 0, 0}, {0, 1, 0}},
                     {{1, 0, 0}, {1, 1, 0}},
                     {{2, 0, 0}, {2, 1, 0}},
                     {{3, 0, 0}, {3, 1, 0}},
                     {{4, 0, 1}, {4, 1, 1}}};
  const BSplineSurface smooth(2, 1, {0, 0, 0, 1, 1, 2, 2, 2}, {0, 0, 1, 1}, Q);
  EXPECT_TRUE(smooth.encloses_on_intervals()) << smooth.interval_refusal();
  EXPECT_TRUE(evaluates_on_intervals(Surface(testing::quarter_arc_cylinder())));
}

TEST(PieceEnclosure, ShrinksWithTheBoxAndBeatsDeCasteljauOnHighDegrees) {
  // A degree 12 x 12 patch with a wavy net.
  ControlNet P(13, std::vector<Vec3>(13));
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j <= 12; ++j)
      P[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          Vec3(i / 12.0, j / 12.0, 2.0 * i * i / 144.0 + 0.3 * std::sin(i + 2.0 * j));
  const BezierPatch b(P);
  double previous = 0;
  for (double h : {0.2, 0.02, 0.002}) {
    const I u(0.4, 0.4 + h), v(0.3, 0.3 + h);
    const double width = b.point(u, v).z.width(), old = b.point_de_casteljau(u, v).z.width();
    EXPECT_LT(width, old) << "box " << h;
    if (previous > 0) {
      EXPECT_LT(width, 0.2 * previous) << "box " << h;  // first order in the box
    }
    previous = width;
    expect_encloses(b, 0.4, 0.4 + h, 0.3, 0.3 + h, "degree 12 patch");
  }
}

}  // namespace
}  // namespace ssimarch
