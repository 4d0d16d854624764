// The patch exclusion of the parametric-parametric certified search (start/patch_exclusion.hpp):
// the assumption behind its implicit test (each primitive's parametric points lie on its own
// implicit form far within kImplicitFormSlack), that no box holding a point of the curve is ever
// excluded, that patches of two nested spheres are excluded without subdividing the other, and
// that the hunt's singular-point test keeps a tangency and excludes a transversal curve.
#include "ssimarch/start/patch_exclusion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "testing/matchers.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {
namespace {

const Vec3 kAxis = Vec3(0.3, -0.5, 0.81).normalized();
const Vec3 kReference = Vec3(0.9, 0.2, 0.1);

// |f(F(u, v))| over a 41 x 41 grid of the domain, relative to `size`, for one primitive.
double worst_disagreement(const Surface& s, double size) {
  const ParamDomain& d = s.domain();
  double worst = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double u = d.u.lo + d.u.width() * i / 40, v = d.v.lo + d.v.width() * j / 40;
      worst = std::max(worst, std::fabs(s.value(s.point(u, v))) / size);
    }
  return worst;
}

TEST(PatchExclusion, ParametricPointsLieOnTheirImplicitFormsFarWithinTheSlack) {
  const Vec3 c(0.4, -1.3, 2.2);
  const std::vector<std::pair<Surface, double>> surfaces{
      {Sphere(c, 1.7, kAxis, kReference), 1.7},
      {Torus(c, kAxis, 2.0, 0.6, kReference), 2.6},
      {Cylinder(c, kAxis, 0.8, {-2, 3}, kReference), 3.0},
      {Cone(c, kAxis, 0.4, {-2, 3}, kReference), 3.0},
      {Ellipsoid(c, {1.5, 0.7, 1.1}, kAxis, kReference), 1.5},
      {Paraboloid(c, kAxis, 0.6, 1.2, {{-2, 2}, {-2, 2}}, kReference), 4.0},
      {Plane(c, kAxis, {{-3, 3}, {-3, 3}}), 3.0},
  };
  // The forms agree to rounding (a few 1e-16): three orders below the slack the search allows.
  for (const auto& [s, size] : surfaces)
    EXPECT_LT(worst_disagreement(s, size), 1e-3 * kImplicitFormSlack) << s.type_name();
}

// Two spheres meeting in a circle (centres 1 apart, radii 1 and 0.8), parametric-parametric.
Problem crossing_spheres() {
  return Problem(Sphere(Vec3::Zero(), 1.0, kAxis, kReference), Sphere(Vec3(1, 0, 0), 0.8, Vec3::UnitZ()),
                 PairKind::kParametricParametric);
}

TEST(PatchExclusion, NoBoxAroundAPointOfTheCurveIsExcluded) {
  const Problem P = crossing_spheres();
  ASSERT_TRUE(patch_exclusion_applies(P));
  // Points of the circle x = (1 + 1 - 0.64) / 2 = 0.68, y^2 + z^2 = 1 - 0.68^2, mapped to both
  // spheres' parameters by Newton (Problem's corrector) from the nearest grid point.
  const double x0 = 0.68, rho = std::sqrt(1 - x0 * x0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int tested = 0;
  for (int k = 0; k < 24; ++k) {
    const double phi = 2 * M_PI * k / 24;
    const Vec3 p(x0, rho * std::cos(phi), rho * std::sin(phi));
    const std::optional<VecX> x = unknowns_near(P, p);
    if (!x) continue;
    ASSERT_THAT(P.point(*x), testing::IsNear(p, 1e-9));
    for (double w : {1e-6, 1e-3, 0.1, 0.5, 2.0}) {
      IntervalNumber box[4];
      for (int i = 0; i < 4; ++i) {
        const double a = unit(rng);  // the point anywhere in the box, faces included
        box[i] = IntervalNumber((*x)[i] - a * w, (*x)[i] + (1 - a) * w);
      }
      EXPECT_FALSE(patches_cannot_meet(P, box)) << "phi " << phi << " width " << w;
      ++tested;
    }
  }
  EXPECT_GE(tested, 100);
}

// Patches of F halved (the wider parameter side) until excluded, the other surface's domain
// whole; returns the number of excluded patches, or -1 when one is still undecided at `depth` 0.
long exclude_by_first_patches(const Problem& P, IntervalNumber u, IntervalNumber v, int depth) {
  const std::vector<Interval>& B = P.bounds();
  const IntervalNumber box[4] = {u, v, {B[2].lo, B[2].hi}, {B[3].lo, B[3].hi}};
  if (patches_cannot_meet(P, box)) return 1;
  if (depth == 0) return -1;
  const bool split_u = u.width() / B[0].width() >= v.width() / B[1].width();
  const IntervalNumber& w = split_u ? u : v;
  const IntervalNumber lo(w.lo(), w.mid()), hi(w.mid(), w.hi());
  const long a =
      split_u ? exclude_by_first_patches(P, lo, v, depth - 1) : exclude_by_first_patches(P, u, lo, depth - 1);
  const long b =
      split_u ? exclude_by_first_patches(P, hi, v, depth - 1) : exclude_by_first_patches(P, u, hi, depth - 1);
  return a < 0 || b < 0 ? -1 : a + b;
}

TEST(PatchExclusion, NestedSpheresAreExcludedByPatchesOfOneAlone) {
  // Radius 0.5 inside radius 1, centres 0.2 apart: at least 0.3 between them. The outer
  // sphere's domain, halved at most 10 times (1024 patches), is excluded patch by patch against
  // the whole domain of the inner one: the componentwise test of H would need patches of both.
  const Problem P(Sphere(Vec3::Zero(), 1.0, kAxis, kReference), Sphere(Vec3(0.2, 0, 0), 0.5),
                  PairKind::kParametricParametric);
  const std::vector<Interval>& B = P.bounds();
  const long patches = exclude_by_first_patches(P, {B[0].lo, B[0].hi}, {B[1].lo, B[1].hi}, 10);
  EXPECT_GT(patches, 0);
  // The swapped pair: the inner sphere's patches against the outer's implicit form.
  const Problem Q(Sphere(Vec3(0.2, 0, 0), 0.5), Sphere(Vec3::Zero(), 1.0, kAxis, kReference),
                  PairKind::kParametricParametric);
  EXPECT_GT(exclude_by_first_patches(Q, {B[0].lo, B[0].hi}, {B[1].lo, B[1].hi}, 10), 0);
}

// The hunt's test: a sphere of radius 1 about (0, 0, 1) touches the plane z = 0 at the origin
// (a singular point: the surfaces are tangent there) and a sphere about (0, 0, 0.5) cuts it
// transversally in the circle of radius sqrt(0.75).
TEST(PatchExclusion, HuntKeepsTheTangencyAndExcludesTheTransversalCircle) {
  const Plane plane(Vec3::Zero(), Vec3::UnitZ(), {{-2, 2}, {-2, 2}});
  const Problem touching(plane, Sphere(Vec3(0, 0, 1), 1.0), PairKind::kParametricImplicit);
  const Problem cutting(plane, Sphere(Vec3(0, 0, 0.5), 1.0), PairKind::kParametricImplicit);
  ASSERT_TRUE(singular_exclusion_applies(touching));
  ASSERT_TRUE(singular_exclusion_applies(cutting));
  // The plane's parameters are coordinates in an orthonormal frame at the origin: the tangency
  // is at (0, 0) and the circle is u^2 + v^2 = 0.75 whatever the frame's rotation.
  const Vec3T<double> o = plane.point(0.0, 0.0);
  ASSERT_LT(std::hypot(o.x, o.y, o.z), 1e-15);
  for (double w : {1e-3, 0.1, 1.0}) {
    for (double a : {0.0, 0.3, 0.9}) {  // the tangency anywhere in the patch, its corner included
      const IntervalNumber u(-a * w, (1 - a) * w), v(-(1 - a) * w, a * w);
      EXPECT_FALSE(patch_holds_no_singular_point(touching, u, v, 12)) << w << " " << a;
    }
  }
  // Patches along the circle (and the disc inside it) hold no singular point: excluded within
  // the halvings allowed, however the patch lies across the circle.
  const double r = std::sqrt(0.75);
  for (int k = 0; k < 16; ++k) {
    const double phi = 2 * M_PI * k / 16, x = r * std::cos(phi), y = r * std::sin(phi);
    const IntervalNumber u(x - 0.2, x + 0.15), v(y - 0.1, y + 0.25);
    EXPECT_TRUE(patch_holds_no_singular_point(cutting, u, v, 12)) << phi;
  }
  // The tangent pair without halvings: the whole domain is not excluded at once, rightly.
  EXPECT_FALSE(patch_holds_no_singular_point(touching, IntervalNumber(-2, 2), IntervalNumber(-2, 2), 0));
}

}  // namespace
}  // namespace ssimarch
