// Packing generators: non-overlap, containment, stability and reproducibility.
#include "ssimarch/porosity/generator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ssimarch/core/error.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch {
namespace {

TEST(porosity_SegmentDistance, MatchesSampling) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 300; ++k) {
    const Vec3 p0(U(rng), U(rng), U(rng)), p1(U(rng), U(rng), U(rng));
    const Vec3 q0(U(rng), U(rng), U(rng));
    const Vec3 q1 = k % 3 == 0 ? q0 + 0.7 * (p1 - p0) : Vec3(U(rng), U(rng), U(rng));  // parallel
    double best = 1e9;
    for (int i = 0; i <= 400; ++i) {
      const Vec3 a = p0 + (p1 - p0) * (i / 400.0);
      // exact distance from a point to the segment q
      const Vec3 d = q1 - q0;
      const double t = std::clamp((a - q0).dot(d) / d.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a - q0 - t * d).norm());
    }
    const double got = segment_distance(p0, p1, q0, q1);
    EXPECT_LE(got, best + 1e-12);
    EXPECT_GE(got, best - 0.01);  // sampling step bound
  }
}

TEST(porosity_DropAndRoll, NonOverlappingInsideAndSupported) {
  SphereBedOptions o;
  o.container_radius = 2.5;
  o.count = 400;
  o.seed = 9;
  GeneratorReport rep;
  const auto ps = drop_and_roll_spheres(o, &rep);
  ASSERT_EQ(ps.size(), 400u);
  EXPECT_EQ(rep.unstable, 0);
  EXPECT_LE(rep.max_overlap, 1e-9);
  const double tol = 1e-8;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const auto& p = ps[i];
    EXPECT_LE(std::hypot(p.centre.x(), p.centre.y()) + p.radius(), o.container_radius + tol);
    EXPECT_GE(p.centre.z() - p.radius(), -tol);
    // Supported: on the floor, or touching a sphere below its centre height.
    bool supported = p.centre.z() - p.radius() <= tol;
    for (std::size_t j = 0; j < ps.size() && !supported; ++j) {
      if (j == i) continue;
      const double gap = (p.centre - ps[j].centre).norm() - p.radius() - ps[j].radius();
      supported = gap <= 1e-7 && ps[j].centre.z() < p.centre.z();
    }
    EXPECT_TRUE(supported) << i;
  }
}

TEST(porosity_DropAndRoll, DeterministicAndDenseEnough) {
  SphereBedOptions o;
  o.container_radius = 3.0;
  o.count = 600;
  o.seed = 4;
  GeneratorReport rep;
  const auto a = drop_and_roll_spheres(o), b = drop_and_roll_spheres(o, &rep);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].centre, b[i].centre);
  // Sequential deposition reaches porosity about 0.42 in the bulk (Visscher & Bolsterli); with the
  // wall at D/d = 6 the region r < R - 1, 2 < z < top - 2 lies between 0.38 and 0.46.
  Container c{2.0, {2.0, rep.height - 2.0}};
  const double eps = bulk_porosity(a, c).porosity;
  EXPECT_GT(eps, 0.36);
  EXPECT_LT(eps, 0.47);
}

// Issue 30: sphere 672 of this bed crept down a shallow slope one 1e-9 d step at a time (5e7 roll
// passes, 39 s). A roll step that descends less than kRollMinSlope of its length halves the step,
// and a step that descends doubles it back, so no sphere takes more than a few hundred passes.
// Counted in passes, not seconds: the bound holds on any machine.
TEST(porosity_DropAndRoll, EverySphereSettlesInFewPasses) {
  SphereBedOptions o;
  o.container_radius = 5.0;
  o.count = 700;
  o.seed = 1;
  GeneratorReport rep;
  const auto bed = drop_and_roll_spheres(o, &rep);
  ASSERT_EQ(static_cast<long>(bed.size()), o.count);
  EXPECT_EQ(rep.unstable, 0);
  EXPECT_LE(rep.max_roll_passes, 2000) << "passes of the slowest sphere";
  EXPECT_LE(rep.roll_passes, 300 * o.count) << "passes in all";
  EXPECT_LE(rep.max_overlap, 1e-6);
}

TEST(porosity_Rsa, NonOverlappingAndInside) {
  SpherocylinderRsaOptions o;
  o.container_radius = 3.0;
  o.diameter = 0.5;
  o.length = 1.0;
  o.count = 300;
  o.seed = 2;
  GeneratorReport rep;
  const auto ps = rsa_spherocylinders(o, &rep);
  ASSERT_EQ(ps.size(), 300u);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (const Vec3& e : {ps[i].plus_cap(), ps[i].minus_cap()}) {
      EXPECT_LE(std::hypot(e.x(), e.y()) + 0.25, 3.0 + 1e-12);
      EXPECT_GE(e.z(), 0.25 - 1e-12);
      EXPECT_LE(e.z(), rep.height - 0.25 + 1e-12);
    }
    for (std::size_t j = i + 1; j < ps.size(); ++j)
      EXPECT_GE(segment_distance(ps[i].minus_cap(), ps[i].plus_cap(), ps[j].minus_cap(), ps[j].plus_cap()), 0.5);
  }
  Container c{3.0, {0.0, rep.height}};
  EXPECT_NEAR(bulk_porosity(ps, c).porosity, 1 - o.target_solid_fraction, 1e-9);
}

TEST(porosity_Generators, RejectImpossibleOptions) {
  SphereBedOptions s;
  s.diameter = -1;
  EXPECT_THROW(drop_and_roll_spheres(s), InputError);
  s.diameter = 20;
  EXPECT_THROW(drop_and_roll_spheres(s), InputError);
  SpherocylinderRsaOptions r;
  r.length = -1;
  try {
    rsa_spherocylinders(r);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "length");
  }
}

}  // namespace
}  // namespace ssimarch
