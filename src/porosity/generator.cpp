// Packing generators. Sources: Visscher & Bolsterli, Nature 239 (1972) 504 (sequential deposition);
// Widom, J. Chem. Phys. 44 (1966) 3888 (random sequential addition); Ericson, Real-Time Collision
// Detection (2005) 5.1.9 (segment-segment distance). See generator.hpp.
#include "ssimarch/porosity/generator.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/core/progress.hpp"
#include "ssimarch/core/text_cat.hpp"

#include "spatial_grid.hpp"

namespace ssimarch {

double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                        const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double tiny = 1e-300;
  double s = 0, t = 0;
  if (a <= tiny && e <= tiny) return r.norm();
  if (a <= tiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p0 + s * d1) - (q0 + t * d2)).norm();
}

namespace {

// Roll step lengths, in particle diameters: the first trial step, and the step below which a sphere
// that still has a descent direction is taken as resting (a thousandth of the contact tolerance's
// default scale would be invisible in any profile).
constexpr double kRollStart = 0.05;
constexpr double kRollStop = 1e-9;
// The least descent of a roll step, as a fraction of its length: a slope of 1e-3 (0.06 degrees).
// A contact set along which the centre descends less is one the sphere cannot roll down any
// further in a way any profile could see; a step that descends less halves the step, so on such a
// set the roll ends after log2(kRollStart / kRollStop) passes instead of creeping down it one
// tolerance at a time (issue 30: 5e7 passes of 1e-9 d for one sphere).
constexpr double kRollMinSlope = 1e-3;
// Passes between two checks of Ctrl-C in one sphere's roll (each pass costs about a microsecond).
constexpr int kRollInterruptPasses = 4096;

// Checks shared by both generators; errors are located by the option's field name.
void check_bed(double container_radius, double diameter, long count) {
  if (!(container_radius > 0) || !std::isfinite(container_radius))
    throw InputError("container_radius", "must be a finite number > 0 (got " + internal::cat(container_radius) + ")");
  if (!(diameter > 0) || !std::isfinite(diameter))
    throw InputError("diameter", "must be a finite number > 0 (got " + internal::cat(diameter) + ")");
  if (count < 0) throw InputError("count", "must be >= 0 (got " + std::to_string(count) + ")");
  // Memory (a particle and its grid entry, about 100 bytes) and time grow linearly; 1e7 particles
  // take about a gigabyte, and a bed of more is beyond what the exact profiles are used for.
  if (count > 10'000'000) throw InputError("count", "must be at most 1e7 (got " + std::to_string(count) + ")");
  if (diameter >= 2 * container_radius)
    throw InputError("diameter", "the particle diameter " + internal::cat(diameter) +
                                     " must be smaller than the container diameter " +
                                     internal::cat(2 * container_radius));
}

class Deposition {
 public:
  explicit Deposition(const SphereBedOptions& o)
      : o_(o), dmax_(std::max(o.diameter, o.diameter_max)), grid_(std::max(o.diameter, o.diameter_max)), rng_(o.seed) {
    check_bed(o.container_radius, o.diameter, o.count);
    if (o.diameter_max != 0 && !(o.diameter_max >= o.diameter && std::isfinite(o.diameter_max)))
      throw InputError("diameter_max",
                       "must be 0 or a finite number >= diameter (got " + internal::cat(o.diameter_max) + ")");
    if (o.diameter_max >= 2 * o.container_radius)
      throw InputError("diameter_max", "the largest diameter " + internal::cat(o.diameter_max) +
                                           " must be smaller than the container diameter " +
                                           internal::cat(2 * o.container_radius));
    tol_ = o.contact_tolerance * o.diameter;
  }

  std::vector<Particle> run(GeneratorReport* rep) {
    std::uniform_real_distribution<double> U(0, 1);
    for (long n = 0; n < o_.count; ++n) {
      throw_if_interrupted();  // Ctrl-C (core/interrupt.hpp)
      report_progress("packing", static_cast<double>(n), static_cast<double>(o_.count));
      const double d = o_.diameter_max > o_.diameter ? o_.diameter + (o_.diameter_max - o_.diameter) * U(rng_) : o_.diameter;
      const double a = d / 2, Rw = o_.container_radius - a;
      const double rr = Rw * std::sqrt(U(rng_)), ph = 2 * std::numbers::pi * U(rng_);
      Vec3 p(rr * std::cos(ph), rr * std::sin(ph), top_ + 2 * dmax_);
      p.z() = fall(p, a, p.z());
      settle(p, a);
      placed_.push_back(make_sphere(p, d));
      grid_.insert(p, static_cast<int>(placed_.size()) - 1);
      top_ = std::max(top_, p.z() + a);
    }
    report_progress("packing", static_cast<double>(o_.count), static_cast<double>(o_.count));
    if (rep) {
      rep->placed = static_cast<long>(placed_.size());
      rep->attempts = rep->placed;
      rep->height = top_;
      rep->unstable = unstable_;
      rep->roll_passes = roll_passes_;
      rep->max_roll_passes = max_roll_passes_;
      rep->max_overlap = max_overlap();
    }
    return placed_;
  }

 private:
  struct Constraint {
    Vec3 n;
    int kind;  // 0 sphere, 1 wall
    int id;
  };

  double fall(const Vec3& p, double a, double z_start) const {
    double best = a;  // floor
    const double amax = dmax_ / 2;
    for (long k = grid_.index(z_start + a + amax); k >= grid_.index(0.0) - 1; --k) {
      if ((k + 1) * grid_.cell() + a + amax < best) break;
      grid_.visit_layer(p.x(), p.y(), a + amax, k, [&](int j) {
        const Particle& s = placed_[j];
        const double D = a + s.radius();
        const double q2 = (p.x() - s.centre.x()) * (p.x() - s.centre.x()) + (p.y() - s.centre.y()) * (p.y() - s.centre.y());
        if (q2 >= D * D) return;
        const double zc = s.centre.z() + std::sqrt(D * D - q2);
        if (zc <= z_start + tol_) best = std::max(best, zc);
      });
    }
    return std::min(best, z_start);
  }

  void gather(const Vec3& p, double a) {
    nb_.clear();
    nb_centre_ = p;
    grid_.visit(p, a + dmax_ / 2 + dmax_, [&](int j) { nb_.push_back(j); });
  }

  double gap_sphere(const Vec3& p, double a, int j) const {
    return (p - placed_[j].centre).norm() - (a + placed_[j].radius());
  }
  double gap_wall(const Vec3& p, double a) const {
    return (o_.container_radius - a) - std::hypot(p.x(), p.y());
  }

  // Pushes p out of the constraints in S that it violates (few sweeps of one-sided projections; a
  // tangential step that lifts the sphere off a contact is left to the next fall).
  void project(Vec3& p, double a, const std::vector<Constraint>& S) const {
    for (int sweep = 0; sweep < 4; ++sweep)
      for (const auto& c : S) {
        if (c.kind == 0) {
          const Vec3& cc = placed_[c.id].centre;
          const double D = a + placed_[c.id].radius();
          const Vec3 w = p - cc;
          const double nw = w.norm();
          if (nw > 0 && nw < D) p = cc + w * (D / nw);
        } else {
          const double q = std::hypot(p.x(), p.y()), Rw = o_.container_radius - a;
          if (q > Rw) {
            p.x() *= Rw / q;
            p.y() *= Rw / q;
          }
        }
      }
  }

  double min_gap(const Vec3& p, double a) const {
    double g = std::min(gap_wall(p, a), p.z() - a);
    for (int j : nb_) g = std::min(g, gap_sphere(p, a, j));
    return g;
  }

  // Steepest feasible descent: minimise |d - g|^2 subject to n_k . d >= 0 (KKT by active-set
  // enumeration over at most three constraints). Returns the equality set used.
  Vec3 descent(const std::vector<Constraint>& act, std::vector<Constraint>& S) const {
    const Vec3 g(0, 0, -1);
    const int m = std::min<int>(static_cast<int>(act.size()), 6);
    auto valid = [&](const std::vector<int>& idx, Vec3& d) {
      const int k = static_cast<int>(idx.size());
      d = g;
      if (k > 0) {
        Eigen::MatrixXd N(3, k);
        for (int i = 0; i < k; ++i) N.col(i) = act[idx[i]].n;
        const Eigen::MatrixXd G = N.transpose() * N;
        Eigen::FullPivLU<Eigen::MatrixXd> lu(G);
        if (lu.rank() < k) return false;
        const Eigen::VectorXd lam = -lu.solve(N.transpose() * g);
        for (int i = 0; i < k; ++i)
          if (lam[i] < -1e-12) return false;
        d = g + N * lam;
      }
      for (int j = 0; j < m; ++j)
        if (std::find(idx.begin(), idx.end(), j) == idx.end() && act[j].n.dot(d) < -1e-12) return false;
      return true;
    };
    Vec3 d;
    std::vector<int> idx;
    if (valid(idx, d)) return d;
    for (int i = 0; i < m; ++i)
      if (valid({i}, d)) return S = {act[i]}, d;
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        if (valid({i, j}, d)) return S = {act[i], act[j]}, d;
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j)
        for (int k = j + 1; k < m; ++k)
          if (valid({i, j, k}, d)) return S = {act[i], act[j], act[k]}, d;
    return Vec3::Zero();  // over-constrained: treat as stable
  }

  // Termination: every roll pass either lowers the centre by at least kRollMinSlope h (and h then
  // doubles back towards kRollStart d: a step shortened at a groove or a new contact does not stay
  // short) or halves h (a step that descends less, or a direction reversed at the bottom of a
  // groove); the roll stops when h falls below kRollStop d. A falling pass follows a pass that left
  // every contact and ends in one. The budget is the bound with every progress pass at the
  // smallest step: never met in practice, so reaching it is a broken invariant, counted unstable.
  void settle(Vec3& p, double a) {
    gather(p, a);
    double h = kRollStart * o_.diameter;
    Vec3 prev_dir = Vec3::Zero();
    const double halvings = std::ceil(std::log2(kRollStart / kRollStop)) + 1;
    const double least_drop = std::max(tol_, kRollMinSlope * kRollStop * o_.diameter);
    const double budget = 2 * (std::ceil((p.z() - a) / least_drop) + 2 * halvings + 2);
    // The passes of this sphere, added to the report however the roll ends.
    struct PassCount {
      long n = 0;
      long *total, *most;
      ~PassCount() {
        *total += n;
        *most = std::max(*most, n);
      }
    } passes{0, &roll_passes_, &max_roll_passes_};
    for (double pass = 0; pass < budget; ++pass) {
      ++passes.n;
      if (passes.n % kRollInterruptPasses == 0) throw_if_interrupted();
      if (p.z() - a <= tol_) return;  // resting on the floor
      if ((p - nb_centre_).norm() > dmax_ / 2) gather(p, a);
      std::vector<Constraint> act;
      for (int j : nb_)
        if (gap_sphere(p, a, j) <= tol_) act.push_back({(p - placed_[j].centre).normalized(), 0, j});
      if (gap_wall(p, a) <= tol_) act.push_back({Vec3(-p.x(), -p.y(), 0).normalized(), 1, -1});
      if (act.empty()) {
        const double z = fall(p, a, p.z());
        if (z < p.z()) {
          p.z() = z;
          continue;
        }
      }
      std::vector<Constraint> S;
      const Vec3 d = descent(act, S);
      const double nd = d.norm();
      if (nd < 1e-10) return;  // gravity balanced by the contacts: stable
      const Vec3 dir = d / nd;
      if (dir.dot(prev_dir) < 0) h *= 0.5;  // overshot the bottom of a groove
      if (h < kRollStop * o_.diameter) return;
      prev_dir = dir;
      auto trial = [&](double s) {
        Vec3 q = p + s * dir;
        project(q, a, S);
        return q;
      };
      Vec3 q = trial(h);
      if (min_gap(q, a) < -tol_) {
        // First new contact along the step, by bisection on the step length.
        double lo = 0, hi = h;
        for (int b = 0; b < 60 && hi - lo > 1e-3 * tol_; ++b) {
          const double mid = (lo + hi) / 2;
          (min_gap(trial(mid), a) < 0 ? hi : lo) = mid;
        }
        q = trial(lo);
        if (min_gap(q, a) < -tol_) {
          ++unstable_;
          return;
        }
      }
      const double step = (q - p).norm();
      if (q.z() > p.z() - std::max(tol_, kRollMinSlope * step))
        h *= 0.5;  // the contact set is (nearly) level along this step: no roll worth the name
      else
        h = std::min(2 * h, kRollStart * o_.diameter);
      p = q;
    }
    ++unstable_;
  }

  double max_overlap() const {
    double worst = 0;
    for (std::size_t i = 0; i < placed_.size(); ++i) {
      const Particle& s = placed_[i];
      grid_.visit(s.centre, dmax_, [&](int j) {
        if (j <= static_cast<int>(i)) return;
        worst = std::max(worst, s.radius() + placed_[j].radius() - (s.centre - placed_[j].centre).norm());
      });
      worst = std::max(worst, std::hypot(s.centre.x(), s.centre.y()) + s.radius() - o_.container_radius);
      worst = std::max(worst, s.radius() - s.centre.z());
    }
    return worst;
  }

  SphereBedOptions o_;
  double dmax_, tol_ = 0, top_ = 0;
  internal::SpatialGrid grid_;
  std::mt19937_64 rng_;
  std::vector<Particle> placed_;
  std::vector<int> nb_;
  Vec3 nb_centre_ = Vec3::Zero();
  long unstable_ = 0;
  long roll_passes_ = 0, max_roll_passes_ = 0;
};

}  // namespace

std::vector<Particle> drop_and_roll_spheres(const SphereBedOptions& opt, GeneratorReport* report) {
  return Deposition(opt).run(report);
}

namespace {

// The placed rods' axis segments in a dense array of cubic cells over the container's box (z
// fastest), each cell holding its segments' end points inline: a neighbour query reads nine
// contiguous runs of cells and no particle record. A hashed grid of indices into the particles
// made every query a chain of cache misses, so the generation time grew faster than N once the
// bed left the cache (1e4 / 1e5 / 1e6 rods: 0.2 / 4.9 / 109 s).
class SegmentGrid {
 public:
  struct Segment {
    Vec3 e0, e1;
  };
  SegmentGrid(double cell, double R, double H)
      : cell_(cell),
        n_(static_cast<long>(std::ceil(2 * R / cell)) + 1),
        nz_(static_cast<long>(std::ceil(H / cell)) + 1),
        R_(R),
        cells_(static_cast<std::size_t>(n_ * n_ * nz_)) {}
  void insert(const Vec3& c, const Segment& s) { cells_[at(ix(c.x()), ix(c.y()), iz(c.z()))].push_back(s); }
  /// Calls f(segment) for the segments whose centres lie in cells within `reach` of c, until f
  /// returns false.
  template <class F>
  void visit(const Vec3& c, double reach, F&& f) const {
    const long i0 = ix(c.x() - reach), i1 = ix(c.x() + reach), j0 = ix(c.y() - reach), j1 = ix(c.y() + reach);
    const long k0 = iz(c.z() - reach), k1 = iz(c.z() + reach);
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j)
        for (long k = k0; k <= k1; ++k)
          for (const Segment& s : cells_[at(i, j, k)])
            if (!f(s)) return;
  }

 private:
  long ix(double v) const { return std::clamp(static_cast<long>(std::floor((v + R_) / cell_)), 0L, n_ - 1); }
  long iz(double v) const { return std::clamp(static_cast<long>(std::floor(v / cell_)), 0L, nz_ - 1); }
  std::size_t at(long i, long j, long k) const { return static_cast<std::size_t>((i * n_ + j) * nz_ + k); }
  double cell_;
  long n_, nz_;
  double R_;
  std::vector<std::vector<Segment>> cells_;
};

}  // namespace

std::vector<Particle> rsa_spherocylinders(const SpherocylinderRsaOptions& o, GeneratorReport* report) {
  check_bed(o.container_radius, o.diameter, o.count);
  if (!(o.length >= 0) || !std::isfinite(o.length))
    throw InputError("length", "must be a finite number >= 0 (got " + internal::cat(o.length) + ")");
  if (!(o.height >= 0) || !std::isfinite(o.height))
    throw InputError("height", "must be a finite number >= 0 (got " + internal::cat(o.height) + ")");
  if (!(o.target_solid_fraction > 0 && o.target_solid_fraction < 1))
    throw InputError("target_solid_fraction", "must be in (0, 1) (got " + internal::cat(o.target_solid_fraction) + ")");
  Particle proto;
  proto.diameter = o.diameter;
  proto.length = o.length;
  double H = o.height;
  if (H <= 0) {
    H = o.count * proto.volume() /
        (o.target_solid_fraction * std::numbers::pi * o.container_radius * o.container_radius);
    H = std::max(H, o.diameter + o.length);
  }
  const double a = o.diameter / 2, h = o.length / 2, Rw = o.container_radius - a;
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N;
  SegmentGrid grid(o.diameter + o.length, o.container_radius, H);
  std::vector<Particle> out;
  long attempts = 0;
  const long max_attempts = o.max_attempts_per_particle * std::max(1L, o.count);
  while (static_cast<long>(out.size()) < o.count && attempts < max_attempts) {
    ++attempts;
    throw_if_interrupted();  // Ctrl-C (core/interrupt.hpp)
    Vec3 u(N(rng), N(rng), N(rng));
    if (!(u.norm() > 0)) continue;
    u.normalize();
    const double rr = Rw * std::sqrt(U(rng)), ph = 2 * std::numbers::pi * U(rng);
    const Vec3 c(rr * std::cos(ph), rr * std::sin(ph), H * U(rng));
    const Vec3 e0 = c - h * u, e1 = c + h * u;
    bool ok = std::hypot(e0.x(), e0.y()) <= Rw && std::hypot(e1.x(), e1.y()) <= Rw;
    ok = ok && std::min(e0.z(), e1.z()) >= a && std::max(e0.z(), e1.z()) <= H - a;
    if (!ok) continue;
    grid.visit(c, o.diameter + o.length, [&](const SegmentGrid::Segment& q) {
      ok = segment_distance(e0, e1, q.e0, q.e1) >= o.diameter;
      return ok;
    });
    if (!ok) continue;
    Particle p = proto;
    p.centre = c;
    p.axis = u;
    out.push_back(p);
    grid.insert(c, {p.minus_cap(), p.plus_cap()});
    report_progress("packing", static_cast<double>(out.size()), static_cast<double>(o.count));
  }
  if (report) {
    report->placed = static_cast<long>(out.size());
    report->attempts = attempts;
    report->height = H;
    report->max_overlap = 0.0;
  }
  return out;
}

}  // namespace ssimarch
