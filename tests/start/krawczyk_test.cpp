// Interval arithmetic and the certified root search (Krawczyk test) on closed-form systems.
#include "ssimarch/start/krawczyk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace ssimarch {
namespace {

template <class F>
SquareSystem make_system(int n, F f) {
  SquareSystem s;
  s.dimension = n;
  s.value = [f](const IntervalNumber* x, IntervalNumber* g) { f(x, g); };
  s.gradient = [f](const IntervalGradient* x, IntervalGradient* g) { f(x, g); };
  return s;
}

IntervalBox box(std::initializer_list<std::pair<double, double>> sides) {
  IntervalBox b;
  for (auto [lo, hi] : sides) b.emplace_back(lo, hi);
  return b;
}

void expect_encloses(const IntervalNumber& a, double lo, double hi) {
  EXPECT_LE(a.lo(), lo) << a;
  EXPECT_GE(a.hi(), hi) << a;
}

TEST(IntervalNumber, EnclosesTheRangeOfEachOperation) {
  const IntervalNumber a(-2.0, 1.0), b(0.1, 3.0);
  expect_encloses(a * a, -2, 4);
  EXPECT_EQ(pow(a, 2).lo(), 0.0);
  expect_encloses(pow(a, 2), 0, 4);
  expect_encloses(sin(b), std::sin(0.1), 1.0);
  EXPECT_LE(sin(b).hi(), 1.0);
  expect_encloses(cos(IntervalNumber(3.0, 3.5)), -1.0, std::cos(3.5));
  expect_encloses(exp(a), std::exp(-2.0), std::exp(1.0));
  expect_encloses(log(b), std::log(0.1), std::log(3.0));
  expect_encloses(sqrt(b), std::sqrt(0.1), std::sqrt(3.0));
  expect_encloses(atan2(IntervalNumber(1.0, 2.0), IntervalNumber(-1.0, 1.0)), std::atan2(1.0, 1.0),
                  std::atan2(1.0, -1.0));
  EXPECT_TRUE(std::isinf((1.0 / a).hi()));  // division by an interval holding 0: the whole line
  // Outward rounding: 0.1 + 0.2 holds the real sum, which no double equals.
  IntervalNumber s = IntervalNumber(0.1) + IntervalNumber(0.2);
  EXPECT_LT(s.lo(), s.hi());
}

TEST(IntervalNumber, NextUpAndDownAgreeWithNextafter) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {1.0, -1.0, 0.1, -3e-310, 5e-324, -5e-324, 1e308, -1e308, std::numeric_limits<double>::max()}) {
    EXPECT_EQ(IntervalNumber::next_up(x), std::nextafter(x, inf)) << x;
    EXPECT_EQ(IntervalNumber::next_down(x), std::nextafter(x, -inf)) << x;
  }
  EXPECT_EQ(IntervalNumber::next_up(0.0), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(IntervalNumber::next_down(-0.0), -std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(IntervalNumber::next_up(inf), inf);
  EXPECT_EQ(IntervalNumber::next_up(-inf), -std::numeric_limits<double>::max());
}

TEST(IntervalNumber, IntegerPowersEncloseTheExactPower) {
  // The exact power of the double, computed in long double (64-bit significand: x^n of a 53-bit
  // x to within 2^-60 relative for these n), lies in the interval, which is a few ulps wide.
  for (double x : {1.1, -1.1, 0.3, -0.7, 3.7e-20, 12345.678})
    for (int n = 2; n <= 12; ++n) {
      long double exact = 1;
      for (int i = 0; i < n; ++i) exact *= static_cast<long double>(x);
      const IntervalNumber p = pow(IntervalNumber(x), n);
      EXPECT_LE(static_cast<long double>(p.lo()), exact) << x << "^" << n;
      EXPECT_GE(static_cast<long double>(p.hi()), exact) << x << "^" << n;
      EXPECT_LE(p.width(), 32 * std::abs(static_cast<double>(exact)) * std::numeric_limits<double>::epsilon())
          << x << "^" << n;
    }
  // An interval across 0: the odd power keeps the sign, the even one starts at 0.
  expect_encloses(pow(IntervalNumber(-1.5, 2.0), 3), -3.375, 8.0);
  EXPECT_EQ(pow(IntervalNumber(-1.5, 2.0), 4).lo(), 0.0);
  expect_encloses(pow(IntervalNumber(-1.5, 2.0), 4), 0.0, 16.0);
}

TEST(Krawczyk, CertifiesBothRootsOfCircleAndLineTo1e12) {
  auto f = [](const auto* x, auto* g) {
    g[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
    g[1] = x[0] - x[1];
  };
  RootSearchResult r = find_all_roots(make_system(2, f), box({{-2, 2}, {-2, 2}}), {});
  EXPECT_TRUE(r.complete());
  ASSERT_EQ(r.roots.size(), 2u);
  for (const CertifiedRoot& root : r.roots)
    for (const IntervalNumber& c : root.enclosure) {
      EXPECT_LE(c.width(), 1e-12);
      EXPECT_NEAR(std::abs(c.mid()), std::numbers::sqrt2 / 2, 1e-12);
      EXPECT_TRUE(c.contains(std::copysign(std::numbers::sqrt2 / 2, c.mid())) || c.width() > 0);
    }
  EXPECT_NE(r.roots[0].x[0] > 0, r.roots[1].x[0] > 0);
}

TEST(Krawczyk, TranscendentalRootAndRootsOnBisectionFacesFoundOnce) {
  RootSearchResult c =
      find_all_roots(make_system(1, [](const auto* x, auto* g) { g[0] = cos(x[0]) - x[0]; }), box({{-10, 10}}), {});
  ASSERT_EQ(c.roots.size(), 1u);
  EXPECT_TRUE(c.complete());
  EXPECT_NEAR(c.roots[0].x[0], 0.7390851332151607, 1e-12);
  EXPECT_TRUE(c.roots[0].enclosure[0].contains(0.7390851332151607) || c.roots[0].enclosure[0].width() < 1e-12);
  // Roots 0.5 and 0.25 lie on the faces of the first two bisections of [0, 1]; 0.1 inside.
  RootSearchResult p =
      find_all_roots(make_system(1, [](const auto* x, auto* g) { g[0] = (x[0] - 0.5) * (x[0] - 0.25) * (x[0] - 0.1); }),
                     box({{0, 1}}), {});
  EXPECT_TRUE(p.complete());
  ASSERT_EQ(p.roots.size(), 3u);
  std::vector<double> found;
  for (const auto& root : p.roots) found.push_back(root.x[0]);
  std::sort(found.begin(), found.end());
  EXPECT_NEAR(found[0], 0.1, 1e-14);
  EXPECT_NEAR(found[1], 0.25, 1e-14);
  EXPECT_NEAR(found[2], 0.5, 1e-14);
}

TEST(Krawczyk, ExcludesARootFreeBoxCompletely) {
  auto f = [](const auto* x, auto* g) {
    g[0] = x[0] * x[0] + x[1] * x[1] + 1.0;
    g[1] = x[0] - x[1];
  };
  RootSearchResult r = find_all_roots(make_system(2, f), box({{-2, 2}, {-2, 2}}), {});
  EXPECT_TRUE(r.roots.empty());
  EXPECT_TRUE(r.complete());
  EXPECT_LE(r.boxes, 16);  // x*x on [-2, 2] is [-4, 4] on intervals: a few bisections first
  // A circle of radius 3 misses the box [-2, 2]^2 except near its corners, which Krawczyk excludes.
  auto g = [](const auto* x, auto* h) {
    h[0] = x[0] * x[0] + x[1] * x[1] - 9.0;
    h[1] = x[0] - x[1];
  };
  RootSearchResult q = find_all_roots(make_system(2, g), box({{-2, 2}, {-2, 2}}), {});
  EXPECT_TRUE(q.roots.empty());
  EXPECT_TRUE(q.complete());
}

TEST(Krawczyk, SingularRootIsReportedUndecidedNotCertified) {
  RootSearchOptions o;
  RootSearchResult r =
      find_all_roots(make_system(1, [](const auto* x, auto* g) { g[0] = x[0] * x[0]; }), box({{-1, 0.7}}), o);
  EXPECT_TRUE(r.roots.empty());
  ASSERT_FALSE(r.undecided.empty());
  for (const UndecidedBox& u : r.undecided) {
    EXPECT_FALSE(u.budget);
    EXPECT_LE(u.box[0].width(), 1.7 * o.min_width);
    EXPECT_NEAR(u.box[0].mid(), 0.0, 1e-6);
  }
}

TEST(Krawczyk, BoxesLeftWhenTheBudgetIsSpentAreReported) {
  auto f = [](const auto* x, auto* g) {
    g[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
    g[1] = x[0] - x[1];
  };
  RootSearchOptions o;
  o.max_boxes = 2;
  RootSearchResult r = find_all_roots(make_system(2, f), box({{-2, 2}, {-2, 2}}), o);
  EXPECT_FALSE(r.complete());
  EXPECT_EQ(r.boxes, 2);
  ASSERT_FALSE(r.undecided.empty());
  for (const UndecidedBox& u : r.undecided) EXPECT_TRUE(u.budget);
}

TEST(Krawczyk, SizedGradientsGiveTheSameSearch) {
  // The circle x^2 + y^2 = 1 against the cubic y = x^3 - x / 2 (two roots), and a 3-unknown
  // system: the search with the n-slot gradients (set_gradients) examines the same boxes and
  // finds the same roots as with the 4-slot one alone (the extra slots only hold zeros).
  auto f2 = [](const auto* x, auto* g) {
    g[0] = x[0] * x[0] + x[1] * x[1] - 1.0;
    g[1] = x[1] - x[0] * x[0] * x[0] + 0.5 * x[0];
  };
  auto f3 = [](const auto* x, auto* g) {
    g[0] = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 1.0;
    g[1] = x[0] - x[1] * x[2];
    g[2] = x[2] - 0.3;
  };
  for (int n : {2, 3}) {
    SquareSystem plain = n == 2 ? make_system(2, f2) : make_system(3, f3);
    SquareSystem sized = plain;
    if (n == 2)
      set_gradients(&sized, f2);
    else
      set_gradients(&sized, f3);
    ASSERT_TRUE(n == 2 ? bool(sized.gradient2) : bool(sized.gradient3));
    const IntervalBox start = n == 2 ? box({{-2, 2}, {-2, 2}}) : box({{-2, 2}, {-2, 2}, {-2, 2}});
    const RootSearchResult a = find_all_roots(plain, start, {}), b = find_all_roots(sized, start, {});
    EXPECT_EQ(a.boxes, b.boxes);
    ASSERT_EQ(a.roots.size(), b.roots.size());
    ASSERT_EQ(a.roots.size(), 2u);
    for (std::size_t i = 0; i < a.roots.size(); ++i) EXPECT_EQ((a.roots[i].x - b.roots[i].x).norm(), 0.0);
  }
}

}  // namespace
}  // namespace ssimarch
