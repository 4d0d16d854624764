// The union of overlapping particles (issue 30): every profile counts a shared volume once.
// References are independent of the library's union code: closed forms (a ball's volume, the lens
// of two balls), the brute-force arc length of the union (largest point-in-solid margin, sampled
// and bisected, tests/porosity/brute_force.hpp) integrated by adaptive quadrature, and Monte Carlo.
#include "ssimarch/porosity/particle_union.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "brute_force.hpp"
#include "ssimarch/porosity/overlaps.hpp"
#include "ssimarch/porosity/profile.hpp"
#include "ssimarch/porosity/quadrature.hpp"
#include "testing/packed_beds.hpp"
#include "thread_group.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

Particle rod(Vec3 c, Vec3 u, double d, double l) { return make_spherocylinder(c, u, d, l); }

// A container holding everything, with the height range of the particles.
Container around(const std::vector<Particle>& ps, double R) {
  Container c;
  c.radius = R;
  c.slab = {1e300, -1e300};
  for (const Particle& p : ps) {
    const double ext = std::abs(p.axis.z()) * p.half_length() + p.radius();
    c.slab.z_min = std::min(c.slab.z_min, p.centre.z() - ext);
    c.slab.z_max = std::max(c.slab.z_max, p.centre.z() + ext);
  }
  return c;
}

ProfileOptions union_options(double tol = 1e-10) {
  ProfileOptions o;
  o.tolerance = tol;
  o.threads = 2;
  return o;
}

TEST(porosity_Union, ThreeCoincidentSpheresHaveThePorosityOfOne) {
  const Particle s = make_sphere({0.3, -0.2, 1.0}, 1.0);
  const std::vector<Particle> three{s, s, s}, one{s};
  const Container c = around(one, 1.5);
  const ProfileOptions opt = union_options();
  const std::vector<double> radii = even_radii(c.radius, 15), edges = even_edges(c.radius, 6),
                            heights = slice_centres(c.slab.z_min, c.slab.z_max, 9);
  const auto r3 = radial_profile(three, c, radii, opt), r1 = radial_profile(one, c, radii, opt);
  const auto b3 = bin_profile(three, c, edges, opt), b1 = bin_profile(one, c, edges, opt);
  const auto a3 = axial_profile(three, c, heights, opt), a1 = axial_profile(one, c, heights, opt);
  const auto m3 = porosity_map(three, c, radii, heights, opt), m1 = porosity_map(one, c, radii, heights, opt);
  for (std::size_t j = 0; j < radii.size(); ++j) EXPECT_NEAR(r3.porosity[j], r1.porosity[j], 1e-9) << "r " << radii[j];
  for (std::size_t j = 0; j + 1 < edges.size(); ++j) EXPECT_NEAR(b3.porosity[j], b1.porosity[j], 1e-9) << "bin " << j;
  for (std::size_t j = 0; j < heights.size(); ++j)
    EXPECT_NEAR(a3.porosity[j], a1.porosity[j], 1e-9) << "z " << heights[j];
  for (std::size_t j = 0; j < m1.porosity.size(); ++j)
    EXPECT_NEAR(m3.porosity[j], m1.porosity[j], 1e-12) << "cell " << j;
  EXPECT_NEAR(bulk_porosity(three, c, opt).solid_volume, s.volume(), 1e-9);
  EXPECT_EQ(r3.stats.overlap_groups, 2);  // the second and third each covered by the first
  // Counted once per particle, the old rule: the shared volume three times.
  ProfileOptions sum = opt;
  sum.overlaps = OverlapRule::kSum;
  EXPECT_NEAR(bulk_porosity(three, c, sum).solid_volume, 3 * s.volume(), 1e-9);
}

TEST(porosity_Union, TwoBallsHoldTheirVolumesLessTheLens) {
  // Offsets along a diagonal, so that the lens meets every profile at an angle.
  const Particle a = make_sphere({0.5, 0.4, 0.0}, 1.2), b = make_sphere({1.0, 0.1, 0.45}, 0.9);
  const double D = (a.centre - b.centre).norm(), lens = sphere_lens_volume(a.radius(), b.radius(), D);
  ASSERT_GT(lens, 1e-3);
  const std::vector<Particle> ps{a, b};
  const Container c = around(ps, 2.5);
  const double want = a.volume() + b.volume() - lens;
  EXPECT_NEAR(bulk_porosity(ps, c, union_options()).solid_volume, want, 1e-9);
  // Bins cutting the lens: their volumes still add up to the union's.
  const auto bins = bin_profile(ps, c, even_edges(c.radius, 7), union_options());
  double v = 0;
  for (std::size_t k = 0; k < bins.porosity.size(); ++k)
    v += (1 - bins.porosity[k]) * kPi * (bins.x_upper[k] * bins.x_upper[k] - bins.x[k] * bins.x[k]) * c.height();
  EXPECT_NEAR(v, want, 1e-8);
  // And the axial areas integrate to it (sections: disks, their lens in closed form).
  const double area = kPi * c.radius * c.radius;
  const QuadResult q = integrate_sqrt_ends(
      [&](double z) {
        const std::vector<double> h{z};
        return (1 - axial_profile(ps, c, h, union_options(1e-13)).porosity[0]) * area;
      },
      c.slab.z_min, c.slab.z_max, 1e-10);
  EXPECT_NEAR(q.value, want, 1e-8);
}

// The lateral area of the union at radius r: the brute-force union arc length integrated over z.
double brute_union_lateral_area(const std::vector<Particle>& ps, const Container& c, double r) {
  return integrate_sqrt_ends([&](double z) { return testing::brute_union_arc_length(ps, z, r, 1024); }, c.slab.z_min,
                             c.slab.z_max, 1e-9)
      .value;
}

// The section area of the union at height z inside the container: brute-force arcs over r.
double brute_union_slice_area(const std::vector<Particle>& ps, const Container& c, double z) {
  return integrate([&](double r) { return testing::brute_union_arc_length(ps, z, r, 1024); }, 0.0, c.radius, 1e-9)
      .value;
}

std::vector<Particle> clump() {
  // A sphere clump crossed by a rod, cut by the container's wall (R = 1.6) and the slab's top.
  return {make_sphere({0.6, 0.2, 0.0}, 1.0), make_sphere({1.0, 0.5, 0.3}, 0.8), make_sphere({0.9, -0.1, 0.5}, 0.7),
          rod({0.7, 0.3, 0.2}, {1, 0.4, 0.5}, 0.4, 1.0)};
}

TEST(porosity_Union, RadialAxialAndMapAgreeWithTheBruteForceUnion) {
  const std::vector<Particle> ps = clump();
  Container c = around(ps, 1.6);
  c.slab.z_max -= 0.2;  // the top of the clump is cut
  const ProfileOptions opt = union_options(1e-10);
  const std::vector<double> radii{0.35, 0.62, 0.9, 1.17, 1.45};
  const auto rad = radial_profile(ps, c, radii, opt);
  for (std::size_t j = 0; j < radii.size(); ++j) {
    const double r = radii[j], area = (1 - rad.porosity[j]) * 2 * kPi * r * c.height();
    EXPECT_NEAR(area, brute_union_lateral_area(ps, c, r), 1e-7) << "r " << r;
  }
  const std::vector<double> heights{-0.45, -0.1, 0.2, 0.41, 0.63};
  const auto ax = axial_profile(ps, c, heights, opt);
  for (std::size_t j = 0; j < heights.size(); ++j) {
    const double area = (1 - ax.porosity[j]) * kPi * c.radius * c.radius;
    // The brute force integrates sampled arcs over r; it misses slivers of about 1e-7 here (see
    // the exact check of three spheres' sections below).
    EXPECT_NEAR(area, brute_union_slice_area(ps, c, heights[j]), 5e-7) << "z " << heights[j];
  }
  const auto map = porosity_map(ps, c, radii, heights, opt);
  for (std::size_t iz = 0; iz < heights.size(); ++iz)
    for (std::size_t ir = 0; ir < radii.size(); ++ir) {
      const double len = (1 - map.porosity[iz * radii.size() + ir]) * 2 * kPi * radii[ir];
      EXPECT_NEAR(len, testing::brute_union_arc_length(ps, heights[iz], radii[ir]), 1e-9)
          << "r " << radii[ir] << " z " << heights[iz];
    }
}

// Area of a union of disks (x, y, s) by Green's theorem: the boundary arcs of each circle outside
// the other disks, integral of (x dy - y dx) / 2 in closed form. An exact, independent reference.
double union_of_disks_area(const std::vector<std::array<double, 3>>& disks) {
  double area = 0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const auto [x, y, s] = disks[i];
    std::vector<double> cuts;
    for (std::size_t j = 0; j < disks.size(); ++j) {
      if (j == i) continue;
      const double dx = disks[j][0] - x, dy = disks[j][1] - y, D = std::hypot(dx, dy), t = disks[j][2];
      if (D >= s + t || D <= std::abs(s - t)) continue;
      const double base = std::atan2(dy, dx), al = std::acos((s * s + D * D - t * t) / (2 * s * D));
      cuts.push_back(std::remainder(base - al, 2 * kPi));
      cuts.push_back(std::remainder(base + al, 2 * kPi));
    }
    if (cuts.empty()) cuts.push_back(-kPi);
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(cuts.front() + 2 * kPi);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double t1 = cuts[k], t2 = cuts[k + 1], tm = (t1 + t2) / 2;
      const double px = x + s * std::cos(tm), py = y + s * std::sin(tm);
      bool covered = false;
      for (std::size_t j = 0; j < disks.size(); ++j)
        covered = covered || (j != i && std::hypot(px - disks[j][0], py - disks[j][1]) < disks[j][2]);
      if (!covered)
        area += (s * s * (t2 - t1) + x * s * (std::sin(t2) - std::sin(t1)) - y * s * (std::cos(t2) - std::cos(t1))) / 2;
    }
  }
  return area;
}

TEST(porosity_Union, SectionsOfThreeBallsAreTheUnionOfTheirDisks) {
  const std::vector<Particle> ps{make_sphere({0.6, 0.2, 0.0}, 1.0), make_sphere({1.0, 0.5, 0.3}, 0.8),
                                 make_sphere({0.9, -0.1, 0.5}, 0.7)};
  const Container c = around(ps, 1.6);
  for (double z : {-0.3, 0.1, 0.25, 0.41, 0.55}) {
    std::vector<std::array<double, 3>> disks;
    for (const Particle& p : ps) {
      const double a = p.radius(), dz = z - p.centre.z();
      if (a * a > dz * dz) disks.push_back({p.centre.x(), p.centre.y(), std::sqrt(a * a - dz * dz)});
    }
    const std::vector<double> h{z};
    const double area = (1 - axial_profile(ps, c, h, union_options(1e-13)).porosity[0]) * kPi * c.radius * c.radius;
    EXPECT_NEAR(area, union_of_disks_area(disks), 1e-12) << "z " << z;
  }
}

// A soft-sphere DEM bed: a dropped-and-rolled bed whose diameters grow by 0.5 %, so that every
// contact becomes a lens of depth 0.005 d. No three balls share a point there, so the union is
// the sum less the lenses, each known independently: its volume in closed form, its sections as
// the union of disks (Green), its area on a cylinder from the brute-force arcs of the pair.
std::vector<Particle> soft_bed() {
  std::vector<Particle> ps = testing::drop_and_roll_bed(2.5, 120, 3).particles;
  for (Particle& p : ps) p.diameter *= 1.005;
  return ps;
}

// A lens of two balls near the wall or across a bin's edge: its sections clipped by a circle are
// the intersection of three disks, by inclusion-exclusion over the Green unions above.
TEST(porosity_Union, ALensCutByACircleIsTheIntersectionOfThreeDisks) {
  const std::vector<Particle> ps{make_sphere({1.55, 0.3, 0.0}, 1.0), make_sphere({1.9, 0.75, 0.35}, 0.9)};
  const std::vector<OverlapGroup> groups = overlap_groups(ps);
  ASSERT_EQ(groups.size(), 1u);
  const OverlapGroup& g = groups[0];
  for (double R : {1.7, 1.95, 2.2})
    for (double z : {-0.05, 0.1, 0.2, 0.3}) {
      std::vector<std::array<double, 3>> d;
      for (const Particle& p : ps) {
        const double a = p.radius(), dz = z - p.centre.z();
        ASSERT_GT(a * a, dz * dz);
        d.push_back({p.centre.x(), p.centre.y(), std::sqrt(a * a - dz * dz)});
      }
      const std::array<double, 3> wall{0.0, 0.0, R};
      auto A = [](std::vector<std::array<double, 3>> v) { return union_of_disks_area(v); };
      const double want = A({d[0]}) + A({d[1]}) + A({wall}) - A({d[0], d[1]}) - A({d[0], wall}) - A({d[1], wall}) +
                          A({d[0], d[1], wall});
      EXPECT_NEAR(covered_slice_area(g, z, R, 1e-12).value, want, 1e-12) << "R " << R << " z " << z;
    }
  // The shells on either side of a circle through the lens hold the lens's volume (closed form).
  const double lens = sphere_lens_volume(0.5, 0.45, (ps[1].centre - ps[0].centre).norm());
  const BedSlab slab{-5, 5};
  double last = 0;
  for (double R : {1.8, 1.9, 2.0, 2.1, 2.2}) {
    const double in = covered_shell_volume(g, 0, R, slab, 1e-13).value,
                 out = covered_shell_volume(g, R, 9, slab, 1e-13).value;
    EXPECT_NEAR(in + out, lens, 1e-12 * lens) << "R " << R;
    EXPECT_GE(in, last) << "R " << R;
    last = in;
  }
}

TEST(porosity_Union, ASoftSphereBedIsItsUnionToTheTolerance) {
  const std::vector<Particle> ps = soft_bed();
  const Container c = around(ps, 2.6);
  std::vector<std::pair<std::size_t, std::size_t>> lenses;
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if ((ps[i].centre - ps[j].centre).norm() < ps[i].radius() + ps[j].radius() - 1e-9) lenses.push_back({j, i});
  ASSERT_GT(lenses.size(), 100u);
  for (const OverlapGroup& g : overlap_groups(ps)) ASSERT_EQ(g.earlier.size(), 1u);  // lenses apart
  // Bulk: the sum of the balls less the lenses.
  double want = 0;
  for (const Particle& p : ps) want += p.volume();
  for (const auto& [j, i] : lenses)
    want -= sphere_lens_volume(ps[i].radius(), ps[j].radius(), (ps[i].centre - ps[j].centre).norm());
  const BulkPorosity bulk = bulk_porosity(ps, c, union_options(1e-8));
  EXPECT_NEAR(bulk.porosity, 1 - want / c.volume(), 1e-8);
  // Axial: the union of the sections' disks.
  const std::vector<double> heights{0.37, 0.93, 1.41};
  const auto ax = axial_profile(ps, c, heights, union_options(1e-8));
  for (std::size_t k = 0; k < heights.size(); ++k) {
    std::vector<std::array<double, 3>> disks;
    for (const Particle& p : ps) {
      const double a = p.radius(), dz = heights[k] - p.centre.z();
      if (a * a > dz * dz) disks.push_back({p.centre.x(), p.centre.y(), std::sqrt(a * a - dz * dz)});
    }
    EXPECT_NEAR(ax.porosity[k], 1 - union_of_disks_area(disks) / (kPi * c.radius * c.radius), 1e-8) << heights[k];
  }
  // Radial: the per-ball sum less each lens's area on the cylinder, from the pair's brute-force arcs.
  ProfileOptions sum = union_options(1e-10);
  sum.overlaps = OverlapRule::kSum;
  const std::vector<double> radii{1.7};
  const auto summed = radial_profile(ps, c, radii, sum), got = radial_profile(ps, c, radii, union_options(1e-8));
  for (std::size_t k = 0; k < radii.size(); ++k) {
    const double r = radii[k];
    double lens_area = 0;
    for (const auto& [j, i] : lenses) {
      const std::vector<Particle> a{ps[i]}, b{ps[j]}, ab{ps[i], ps[j]};
      // The lens lies in the ball on the circle where the spheres meet, of radius
      // sqrt(rho^2 + h^2) (h the taller cap): integrate over that ball's heights, on 16 panels.
      const Vec3 n = (ps[j].centre - ps[i].centre).normalized();
      const double D = (ps[j].centre - ps[i].centre).norm(), ai = ps[i].radius(), aj = ps[j].radius();
      const double t = (D * D + ai * ai - aj * aj) / (2 * D);
      const Vec3 c0 = ps[i].centre + t * n;
      const double cap = std::max(ai - t, aj - (D - t)), RL = std::sqrt(ai * ai - t * t + cap * cap);
      if (std::abs(std::hypot(c0.x(), c0.y()) - r) > RL) continue;
      auto common = [&](double z) {
        return testing::brute_union_arc_length(a, z, r, 512) + testing::brute_union_arc_length(b, z, r, 512) -
               testing::brute_union_arc_length(ab, z, r, 512);
      };
      for (int m = 0; m < 16; ++m)
        lens_area += integrate(common, c0.z() - RL + 2 * RL * m / 16, c0.z() - RL + 2 * RL * (m + 1) / 16, 1e-13).value;
    }
    const double norm = 2 * kPi * r * c.height();
    EXPECT_NEAR(got.porosity[k], summed.porosity[k] + lens_area / norm, 1e-8) << "r " << r;
  }
}

// A random bed of clumps (three spheres per particle, heavily overlapping, and the clumps touching
// each other), the shape multi-sphere DEM models write.
std::vector<Particle> clumped_bed(int clumps, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<Particle> ps;
  for (int k = 0; k < clumps; ++k) {
    const Vec3 c(1.6 * U(rng), 1.6 * U(rng), 1.5 * U(rng));
    for (int m = 0; m < 3; ++m) ps.push_back(make_sphere(c + 0.25 * Vec3(U(rng), U(rng), U(rng)), 0.5 + 0.2 * U(rng)));
  }
  return ps;
}

TEST(porosity_Union, AClumpedBedAgreesWithMonteCarlo) {
  const std::vector<Particle> ps = clumped_bed(12, 5);
  const Container c = around(ps, 2.0);
  const BulkPorosity bulk = bulk_porosity(ps, c, union_options(1e-9));
  // Uniform points in the container, inside the union or not.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const long n = 400'000;
  long inside = 0;
  for (long k = 0; k < n; ++k) {
    const double rr = c.radius * std::sqrt(U(rng)), th = 2 * kPi * U(rng);
    const Vec3 p(rr * std::cos(th), rr * std::sin(th), c.slab.z_min + c.height() * U(rng));
    for (const Particle& q : ps)
      if (inside_margin(q, p) > 0) {
        ++inside;
        break;
      }
  }
  const double f = static_cast<double>(inside) / n, sigma = std::sqrt(f * (1 - f) / n);
  EXPECT_NEAR(1 - bulk.porosity, f, 5 * sigma);
  ProfileOptions sum = union_options(1e-9);
  sum.overlaps = OverlapRule::kSum;
  EXPECT_GT(bulk_porosity(ps, c, sum).solid_volume - bulk.solid_volume, 20 * sigma * c.volume());
}

TEST(porosity_Union, ThreadsAndRanksGiveTheSameBits) {
  const std::vector<Particle> ps = clumped_bed(10, 9);
  const Container c = around(ps, 2.0);
  const std::vector<double> radii = even_radii(c.radius, 12);
  ProfileOptions one = union_options(1e-8);
  one.threads = 1;
  const auto ref = radial_profile(ps, c, radii, one);
  const auto threads = radial_profile(ps, c, radii, union_options(1e-8));
  for (std::size_t j = 0; j < radii.size(); ++j) EXPECT_EQ(ref.porosity[j], threads.porosity[j]);
  const int n = 3;
  testing::ThreadGroup group(n);
  std::vector<std::vector<double>> got(n);
  std::vector<std::thread> ranks;
  for (int k = 0; k < n; ++k)
    ranks.emplace_back([&, k] {
      testing::ThreadGroup::Member me(group, k);
      ProfileOptions o = one;
      o.communicator = &me;
      const std::size_t b = ps.size() * k / n, e = ps.size() * (k + 1) / n;
      got[static_cast<std::size_t>(k)] =
          radial_profile(std::span<const Particle>(ps).subspan(b, e - b), c, radii, o).porosity;
    });
  for (auto& t : ranks) t.join();
  for (int k = 0; k < n; ++k)
    for (std::size_t j = 0; j < radii.size(); ++j) EXPECT_EQ(got[static_cast<std::size_t>(k)][j], ref.porosity[j]);
}

TEST(porosity_Union, GroupsSplitIntoComponentsThatLieApart) {
  // A sphere touched at its two poles by two others: two groups, one lens each.
  const Particle mid = make_sphere({0, 0, 0}, 1.0);
  const std::vector<Particle> ps{make_sphere({0, 0, 0.99}, 1.0), make_sphere({0, 0, -0.99}, 1.0), mid};
  const auto groups = overlap_groups(ps);
  ASSERT_EQ(groups.size(), 2u);
  for (const OverlapGroup& g : groups) {
    EXPECT_EQ(g.earlier.size(), 1u);
    EXPECT_TRUE(g.spheres());
  }
}

}  // namespace
}  // namespace ssimarch
