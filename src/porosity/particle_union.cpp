// Measures of the covered part P_i n U_i of an overlap group (particle_union.hpp). Source:
// docs/math/particle_union.md (ownership by index, the breakpoints of the covered length).
#include "ssimarch/porosity/particle_union.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>
#include <string>

#include "covered_chords.hpp"
#include "disk_union.hpp"
#include "meeting_circle.hpp"
#include "interval_cover.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/porosity/quadrature.hpp"
#include "ssimarch/porosity/polynomial_roots.hpp"
#include "ssimarch/porosity/sphere_arc.hpp"

namespace ssimarch {

namespace {

// Samples over a whole window where the breakpoints are not closed forms (spherocylinder groups):
// the density of the kernel formulation's signature search (particle_integrals.cpp).
constexpr int kOrderSamples = 256;
using internal::meet_angles;
using internal::meet_point;
using internal::MeetCircle;
using internal::meeting_circles;
using internal::planar_radius2;
using internal::Span;
using internal::trig2_roots;
using internal::TrigRoot;

// The members of a group: the particle first, then the earlier ones.
std::vector<ParticleShape> shapes_of(const OverlapGroup& g) {
  std::vector<ParticleShape> s;
  s.reserve(g.earlier.size() + 1);
  s.emplace_back(g.particle);
  for (const Particle& p : g.earlier) s.emplace_back(p);
  return s;
}

// Order of the members' interval ends (label 2k + end): constant where the covered length is
// analytic in the members' own ends.
long order_signature(std::vector<std::pair<double, int>>& ends) {
  std::sort(ends.begin(), ends.end());
  std::uint64_t h = 1469598103934665603ull;
  for (const auto& e : ends) h = (h ^ static_cast<std::uint64_t>(e.second + 1)) * 1099511628211ull;
  return static_cast<long>(h >> 1);
}

// Samples of where a spherocylinder group's covered area is positive, over its range of radii (each
// sample is a whole lateral-area integral).
constexpr int kSupportSamples = 32;

// Bisection steps that locate a change of the order between two samples: to 2^-40 of their
// spacing, below which a kink left inside a piece costs the adaptive rule nothing measurable.
constexpr int kLocateSteps = 40;

// Integrates f over the pieces [br[k], br[k+1]]: analytic pieces (spheres) with square-root ends.
// Otherwise the order of interval ends is sampled (kOrderSamples over the whole range) and, between
// two samples that differ, one change located by bisection and made a breakpoint; the work is
// bounded by the samples, and a second change between the same two samples stays a kink inside a
// piece for the adaptive rule.
template <class F, class S>
QuadResult integrate_pieces(const std::vector<double>& br, bool analytic, double abs_tol, F&& f, S&& sig,
                            int samples = kOrderSamples) {
  QuadResult out;
  const double W = br.back() - br.front();
  std::vector<double> cuts;
  for (std::size_t k = 0; k + 1 < br.size(); ++k) {
    const double a = br[k], b = br[k + 1], w = b - a;
    if (!(w > 0)) continue;
    const double tol = abs_tol * w / W;
    if (analytic) {
      // Between two breakpoints no interval appears, vanishes or passes another's end, so a piece
      // whose midpoint is not covered is not covered anywhere (the common case around a lens).
      ++out.evaluations;
      if (f((a + b) / 2) != 0) out += integrate_sqrt_ends(f, a, b, tol);
      continue;
    }
    const int n = std::max(8, static_cast<int>(samples * w / W));
    cuts.assign(1, a);
    double xl = a;
    long sl = sig(a);
    for (int j = 1; j <= n; ++j) {
      const double xr = j == n ? b : a + w * j / n;
      const long sr = sig(xr);
      if (sr != sl) {
        double lo = xl, hi = xr;
        for (int it = 0; it < kLocateSteps; ++it) {
          const double m = (lo + hi) / 2;
          (sig(m) == sl ? lo : hi) = m;
        }
        cuts.push_back((lo + hi) / 2);
      }
      xl = xr;
      sl = sr;
    }
    cuts.push_back(b);
    out.evaluations += n + 1 + kLocateSteps * static_cast<long>(cuts.size() - 2);
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j)
      out += integrate_sqrt_ends(f, cuts[j], cuts[j + 1], tol * (cuts[j + 1] - cuts[j]) / w);
  }
  return out;
}

// Arcs of the circle (r, z) inside a particle, appended as spans of [-pi, pi].
void circle_arcs(const Particle& p, double z, double r, std::vector<Span>& out) {
  if (p.length == 0) {
    const double a = p.radius(), dz = z - p.centre.z(), s2 = (a - dz) * (a + dz);
    if (s2 < 0) return;
    const double rho = std::hypot(p.centre.x(), p.centre.y());
    if (rho == 0) {
      if (r * r <= s2) internal::add_arc(out, -std::numbers::pi, 2 * std::numbers::pi);
      return;
    }
    const double cs = (r * r + rho * rho - s2) / (2 * r * rho);
    if (cs >= 1) return;
    const double al = cs <= -1 ? std::numbers::pi : std::acos(cs);
    internal::add_arc(out, std::atan2(p.centre.y(), p.centre.x()) - al, 2 * al);
    return;
  }
  const auto res = circle_spherocylinder(p, z, r);
  if (res.count == 0) {
    if (res.inside_length > 0) internal::add_arc(out, -std::numbers::pi, 2 * std::numbers::pi);
    return;
  }
  // Arcs between consecutive crossings, kept where their midpoint is inside (tangencies give empty
  // arcs).
  for (int k = 0; k < res.count; ++k) {
    const double b = res.crossing_angles[static_cast<std::size_t>(k)];
    const double e = k + 1 < res.count ? res.crossing_angles[static_cast<std::size_t>(k + 1)]
                                       : res.crossing_angles[0] + 2 * std::numbers::pi;
    if (!(e > b)) continue;
    const double m = (b + e) / 2;
    if (inside_margin(p, Vec3(r * std::cos(m), r * std::sin(m), z)) > 0) internal::add_arc(out, b, e - b);
  }
}

// Covered angle at (r, z) (radians) and, for sampling, the order of the members' arc ends.
struct ArcScratch {
  std::vector<Span> own, others;
  std::vector<std::pair<double, int>> ends;
};

double covered_angle(const OverlapGroup& g, double z, double r, ArcScratch& s, long* sig = nullptr) {
  s.own.clear();
  s.others.clear();
  circle_arcs(g.particle, z, r, s.own);
  for (const Particle& p : g.earlier) circle_arcs(p, z, r, s.others);
  if (sig) {
    // Only the ends that decide the covered length: the other arcs clipped to each own arc.
    s.ends.clear();
    int label = 0;
    for (const Span& a : s.own) {
      s.ends.push_back({a.lo, label}), s.ends.push_back({a.hi, label + 1});
      label += 2;
      for (const Span& o : s.others) {
        const double l = std::max(o.lo, a.lo), h = std::min(o.hi, a.hi);
        if (h > l) s.ends.push_back({l, label}), s.ends.push_back({h, label + 1});
        label += 2;
      }
    }
    *sig = order_signature(s.ends);
  }
  return internal::covered_length(s.own, s.others);
}

// Sections of a group of balls by the plane z: the area of D_i n (D_j1 u D_j2 u ...) in closed
// form, A(D_i) + A(u D_j) - A(D_i u D_j1 u ...) (disk_union.hpp).
struct SectionScratch {
  std::vector<internal::Disk> disks;
  std::vector<double> cuts;
};

double covered_section_area(const OverlapGroup& g, double z, SectionScratch& s, double R = -1) {
  auto disk = [&](const Particle& p, internal::Disk& d) {
    const double a = p.radius(), dz = z - p.centre.z(), s2 = (a - dz) * (a + dz);
    d = {p.centre.x(), p.centre.y(), s2 > 0 ? std::sqrt(s2) : 0.0};
    return s2 > 0;
  };
  // The covered part lies in the group's box: a disk missing the box holds none of it, one
  // holding the box all of it.
  if (R >= 0 && R <= g.rho_min()) return 0.0;
  if (R >= g.rho_max()) R = -1;
  internal::Disk own;
  if (!disk(g.particle, own)) return 0.0;
  if (g.earlier.size() == 1) {
    // One lens: the intersection of two disks, inside the clip disk when there is one.
    internal::Disk other;
    if (!disk(g.earlier[0], other)) return 0.0;
    if (R < 0) return disk_disk_area(own.s, other.s, std::hypot(other.x - own.x, other.y - own.y));
    return internal::intersection_of_three_disks_area(own, other, {0.0, 0.0, R});
  }
  s.disks.clear();
  for (const Particle& p : g.earlier) {
    internal::Disk d;
    if (disk(p, d)) s.disks.push_back(d);
  }
  if (s.disks.empty()) return 0.0;
  const internal::Disk container{0.0, 0.0, R};
  const internal::Disk* clip = R > 0 ? &container : nullptr;
  const double others = internal::union_of_disks_area(s.disks, s.cuts, clip);
  s.disks.push_back(own);
  const double all = internal::union_of_disks_area(s.disks, s.cuts, clip);
  s.disks.assign(1, own);
  const double mine = clip ? internal::union_of_disks_area(s.disks, s.cuts, clip) : std::numbers::pi * own.s * own.s;
  return std::max(0.0, mine + others - all);
}

// Heights where the sections' arrangement changes: a member's section appears or vanishes, two
// sections' circles become tangent (the top and bottom of the circle where two spheres meet).
// With cylinders of the given radii (those <= 0 ignored): a section's circle tangent to a
// cylinder's, and a meeting circle passing through a cylinder.
std::vector<double> section_heights(const OverlapGroup& g, std::initializer_list<double> cylinders) {
  std::vector<double> zs;
  std::vector<const Particle*> ms{&g.particle};
  for (const Particle& p : g.earlier) ms.push_back(&p);
  for (const Particle* p : ms) {
    const double a = p->radius(), rho = std::hypot(p->centre.x(), p->centre.y());
    zs.push_back(p->centre.z() - a), zs.push_back(p->centre.z() + a);
    for (double R : cylinders)
      for (double sr : {std::abs(R - rho), R + rho})
        if (R > 0 && sr < a) {
          const double h = std::sqrt((a - sr) * (a + sr));
          zs.push_back(p->centre.z() - h), zs.push_back(p->centre.z() + h);
        }
  }
  std::vector<MeetCircle> circles;
  meeting_circles(g, circles);
  for (const MeetCircle& m : circles) {
    const double nz = m.e1.cross(m.e2).z(), h = m.rho * std::sqrt(std::max(0.0, 1 - nz * nz));
    zs.push_back(m.c.z() - h), zs.push_back(m.c.z() + h);
    for (double R : cylinders)
      if (R > 0) {
        const auto f = planar_radius2(m);
        std::array<TrigRoot, 4> psi{};
        const int n = trig2_roots(f[0] - R * R, f[1], f[2], f[3], f[4], psi);
        for (int k = 0; k < n; ++k) zs.push_back(meet_point(m, psi[static_cast<std::size_t>(k)]).z());
      }
  }
  return zs;
}

}  // namespace

const char* to_string(OverlapRule rule) { return rule == OverlapRule::kUnion ? "union" : "sum"; }

OverlapRule overlap_rule_named(std::string_view name, const char* key) {
  if (name == "union") return OverlapRule::kUnion;
  if (name == "sum") return OverlapRule::kSum;
  throw InputError(key,
                   "must be 'union' (a shared volume counted once, the default) or 'sum' (once per particle "
                   "holding it), got '" +
                       std::string(name) + "'");
}

double OverlapGroup::rho_min() const {
  const double x = std::max({box_lo.x(), -box_hi.x(), 0.0}), y = std::max({box_lo.y(), -box_hi.y(), 0.0});
  return std::hypot(x, y);
}

double OverlapGroup::rho_max() const {
  return std::hypot(std::max(std::abs(box_lo.x()), std::abs(box_hi.x())),
                    std::max(std::abs(box_lo.y()), std::abs(box_hi.y())));
}

bool OverlapGroup::spheres() const {
  return particle.length == 0 &&
         std::all_of(earlier.begin(), earlier.end(), [](const Particle& p) { return p.length == 0; });
}

double covered_arc_length(const OverlapGroup& g, double z, double r) {
  if (z < g.box_lo.z() || z > g.box_hi.z() || r < g.rho_min() || r > g.rho_max()) return 0.0;
  ArcScratch s;
  return r * covered_angle(g, z, r, s);
}

QuadResult covered_lateral_area(const OverlapGroup& g, double r, const BedSlab& slab, double abs_tol) {
  if (!(r > 0) || r < g.rho_min() || r > g.rho_max()) return {};
  if (std::max(slab.z_min, g.box_lo.z()) >= std::min(slab.z_max, g.box_hi.z())) return {};
  const auto [lo, hi] = internal::angular_window(g.box_lo, g.box_hi);
  // Balls: every breakpoint is a closed form, and so is each piece (covered_chords.hpp).
  if (g.spheres()) return internal::CoveredBallChords(g, slab).lateral_area(r);
  const std::vector<ParticleShape> ms = shapes_of(g);
  // Breakpoints: shadow ends, cylinder-cap junctions and slab cuts of every member, and the lines
  // through the circles where two member spheres meet.
  std::vector<double> angles;
  const bool cut = slab.z_min > g.box_lo.z() || slab.z_max < g.box_hi.z();
  for (const ParticleShape& m : ms) {
    std::array<Arc, 4> arcs;
    bool full = false;
    const int n = m.shadow_arcs(r, arcs, full);
    for (int k = 0; k < n; ++k)
      angles.push_back(arcs[static_cast<std::size_t>(k)].begin),
          angles.push_back(arcs[static_cast<std::size_t>(k)].end);
    std::array<double, 8> more{};
    int nm = m.junction_angles(r, more);
    angles.insert(angles.end(), more.begin(), more.begin() + nm);
    if (cut) {
      nm = m.clip_angles(r, slab.z_min, more, 0);
      nm = m.clip_angles(r, slab.z_max, more, nm);
      angles.insert(angles.end(), more.begin(), more.begin() + nm);
    }
  }
  std::vector<MeetCircle> circles;
  meeting_circles(g, circles);
  for (const MeetCircle& c : circles) meet_angles(c, r, angles);
  const std::vector<double> br = internal::breakpoints_in(angles, lo, hi, true);
  std::vector<Span> own(1), others;
  std::vector<std::pair<double, int>> ends;
  // Chords of the members on the line over (r, theta), cut by the slab; the covered chord length.
  auto chords = [&](double th, bool order) {
    const double x = r * std::cos(th), y = r * std::sin(th);
    others.clear();
    ends.clear();
    for (std::size_t k = 0; k < ms.size(); ++k) {
      const Chord c = ms[k].vertical_chord(x, y);
      const double l = std::max(c.lo, slab.z_min), h = std::min(c.hi, slab.z_max);
      if (c.empty() || !(h > l)) {
        if (k == 0) return 0.0;
        continue;
      }
      if (k == 0)
        own[0] = {l, h};
      else
        others.push_back({l, h});
    }
    if (order) {
      // Only the ends that decide the covered length: each other chord clipped to the own chord.
      ends.push_back({own[0].lo, 0}), ends.push_back({own[0].hi, 1});
      int label = 2;
      for (const Span& o : others) {
        const double l = std::max(o.lo, own[0].lo), h = std::min(o.hi, own[0].hi);
        if (h > l) ends.push_back({l, label}), ends.push_back({h, label + 1});
        label += 2;
      }
    }
    return internal::covered_length(own, others);
  };
  QuadResult out = integrate_pieces(
      br, g.spheres(), abs_tol / r, [&](double th) { return chords(th, false); },
      [&](double th) {
        chords(th, true);
        return order_signature(ends);
      });
  out.value *= r;
  out.error *= r;
  return out;
}

QuadResult covered_shell_volume(const OverlapGroup& g, double r0, double r1, const BedSlab& slab, double abs_tol) {
  const bool inside =
      g.rho_min() >= r0 && g.rho_max() <= r1 && g.box_lo.z() >= slab.z_min && g.box_hi.z() <= slab.z_max;
  r0 = std::max(r0, g.rho_min());
  r1 = std::min(r1, g.rho_max());
  if (!(r1 > r0)) return {};
  if (inside && g.spheres() && g.earlier.size() == 1) {
    // One lens wholly in the shell: the closed form of overlaps.hpp.
    QuadResult q;
    q.value = sphere_lens_volume(g.particle.radius(), g.earlier[0].radius(),
                                 (g.particle.centre - g.earlier[0].centre).norm());
    q.evaluations = 1;
    return q;
  }
  if (g.spheres()) {
    // Balls: the closed-form section areas inside the disk of radius r1 less those inside r0,
    // integrated over z with the heights where their arrangement changes as breakpoints.
    const double z0 = std::max(g.box_lo.z(), slab.z_min), z1 = std::min(g.box_hi.z(), slab.z_max);
    if (!(z1 > z0)) return {};
    SectionScratch s;
    // Only a cylinder passing through the group's box changes the sections' arrangement.
    const double rc0 = r0 > g.rho_min() ? r0 : -1, rc1 = r1 < g.rho_max() ? r1 : -1;
    const std::vector<double> br = internal::breakpoints_in(section_heights(g, {rc0, rc1}), z0, z1, false);
    return integrate_pieces(
        br, true, abs_tol,
        [&](double z) { return covered_section_area(g, z, s, r1) - covered_section_area(g, z, s, r0); },
        [](double) { return 0L; });
  }
  // Inner tolerance a tenth of the outer one per unit radius (as shell_volume).
  const double inner = 0.1 * abs_tol / (r1 - r0);
  QuadResult stats;
  auto A = [&](double r) {
    // A heavily overlapping rod group takes seconds: Ctrl-C is honoured between its lateral areas.
    throw_if_interrupted();
    const QuadResult q = covered_lateral_area(g, r, slab, inner);
    stats.evaluations += q.evaluations;
    if (q.status != QuadStatus::kConverged) stats.status = q.status;
    return q.value;
  };
  // Spherocylinders: where the covered area starts and stops (a cylinder touching the covered
  // part) and its kinks (meeting curves of two members touching a cylinder) are no closed forms.
  QuadResult out = integrate_pieces(
      {r0, r1}, false, 0.9 * abs_tol, A, [&](double r) { return A(r) > 0 ? 1L : 0L; }, kSupportSamples);
  out.evaluations += stats.evaluations;
  if (stats.status != QuadStatus::kConverged) out.status = stats.status;
  return out;
}

QuadResult covered_slice_area(const OverlapGroup& g, double z, double R, double abs_tol) {
  if (z <= g.box_lo.z() || z >= g.box_hi.z()) return {};
  const double r0 = g.rho_min(), r1 = std::min(R, g.rho_max());
  if (!(r1 > r0)) return {};
  auto section = [&](const Particle& p) {
    const double a = p.radius(), dz = z - p.centre.z();
    return std::sqrt(std::max(0.0, (a - dz) * (a + dz)));
  };
  if (g.spheres()) {
    // Disks: the area of their union inside the container's disk in closed form.
    SectionScratch s;
    QuadResult out;
    out.value = covered_section_area(g, z, s, R);
    out.evaluations = 1;
    return out;
  }
  // Breakpoints in r: where the circle is tangent to a member's section and, for spheres, where it
  // passes through the points where two sections' circles cross.
  std::vector<double> radii;
  std::vector<const Particle*> ms{&g.particle};
  for (const Particle& p : g.earlier) ms.push_back(&p);
  for (const Particle* p : ms) {
    const ParticleShape s(*p);
    radii.push_back(s.rho_min()), radii.push_back(s.rho_max());
    if (p->length != 0) continue;
    const double sr = section(*p), rho = std::hypot(p->centre.x(), p->centre.y());
    radii.push_back(std::abs(rho - sr)), radii.push_back(rho + sr);
  }
  for (std::size_t a = 0; a < ms.size(); ++a)
    for (std::size_t b = a + 1; b < ms.size(); ++b) {
      if (ms[a]->length != 0 || ms[b]->length != 0) continue;
      const double ra = section(*ms[a]), rb = section(*ms[b]);
      const double dx = ms[b]->centre.x() - ms[a]->centre.x(), dy = ms[b]->centre.y() - ms[a]->centre.y();
      const double d = std::hypot(dx, dy);
      if (!(d > 0) || d >= ra + rb || d <= std::abs(ra - rb)) continue;
      const double t = (d * d + ra * ra - rb * rb) / (2 * d), h = std::sqrt(std::max(0.0, ra * ra - t * t));
      const double mx = ms[a]->centre.x() + t * dx / d, my = ms[a]->centre.y() + t * dy / d;
      radii.push_back(std::hypot(mx - h * dy / d, my + h * dx / d));
      radii.push_back(std::hypot(mx + h * dy / d, my - h * dx / d));
    }
  const std::vector<double> br = internal::breakpoints_in(radii, r0, r1, false);
  ArcScratch s;
  return integrate_pieces(
      br, false, abs_tol, [&](double r) { return r * covered_angle(g, z, r, s); },
      [&](double r) {
        long sig = 0;
        covered_angle(g, z, r, s, &sig);
        return sig;
      });
}

}  // namespace ssimarch
