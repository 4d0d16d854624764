// Curves cut to the trimming loops of CAD faces (docs/cad.md, "Trimming loops"). A boundary
// crossing between two traced points is a root of the signed distance phi(x) = min over the
// regions of (p(x) - c) . inward along the curve; at the root p lies on both surfaces and on the
// boundary curve itself (p - c is normal to the boundary tangent and to the face's inward
// direction, so along the normal: zero for a point of the surface near c).
#include "ssimarch/pipeline/face_clip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "ssimarch/march/model_size.hpp"

#include "ssimarch/analytic/conic_pieces.hpp"
#include "ssimarch/march/arc_length.hpp"
#include "ssimarch/march/refined_arc_length.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/pipeline/edge_surface_points.hpp"
#include "ssimarch/pipeline/parameter_loops.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/gauss_newton.hpp"

namespace ssimarch {

namespace {

// Points of a traced curve within this distance (relative to the model size) of a face's
// boundary, two or more in a row, run along the boundary rather than across it: a curve that is
// itself a face edge (a rod in a hole of its own radius: the rod meets the hole's face along the
// hole's edge) lies on the boundary to the accuracy of the model's surfaces, not to the trace's
// tolerance (as1-oc-214: the rod's B-spline is 2.4e-5 mm off the hole's circle, 1.2e-7 of the
// pair's size, above the file's stated uncertainty of 1e-5 mm), so its points fall on either side
// at random and the clip cut it into fragments (4 pieces of 6.7 of a half circle of 15.7). A
// closed face holds its boundary: such runs are kept, and the result says they were decided by
// this band, not certified. A transversal crossing puts at most one point in the band unless its
// steps are shorter than band / sin(angle), i.e. unless it is itself nearly along the boundary.
// Dimensionless.
constexpr double kBoundaryBand = 1e-6;

// |phi| to which a crossing is solved on the curve, relative to max(1, model size)
// (dimensionless): a hundred rounding units of the coordinates. A traced point (or one added at
// a boundary point) this close to the boundary is a crossing as it stands.
constexpr double kCrossingAccuracy = 1e-13;

struct Clipper {
  const Problem& problem;
  std::array<const FaceRegion*, 2> regions;
  CorrectorOptions corrector;
  double scale;  // max(1, model size)
  std::array<std::optional<ParameterLoops>, 2> loops;  // regions[k]'s loops on the Problem's surface k
};

// Whether a point at signed distance phi from the nearest boundary is decided in the parameter
// planes: beyond the band and beyond four times the sampled loops' resolution (nearer, the 3D
// sign is exact and the samples' chords are not).
bool far_from_boundary(const Clipper& c, double phi) {
  double near = kBoundaryBand * c.scale;
  for (const auto& l : c.loops)
    if (l) near = std::max(near, 4 * l->resolution());
  return std::abs(phi) > near;
}

// The side of a point far from every boundary (far_from_boundary): in each region's parameter
// plane where its loops are there (parameter_loops.hpp), else by the 3D sign.
bool inside_far(const Clipper& c, const Vec3& p, const VecX& x) {
  const Linearization L = c.problem.linearize(x);
  for (std::size_t k = 0; k < 2; ++k) {
    if (!c.regions[k]) continue;
    const Surface& s = k == 0 ? c.problem.first() : c.problem.second();
    if (c.loops[k]) {
      if (const std::optional<Vec2> uv = closest_parameters(s, p)) {
        if (!c.loops[k]->contains(*uv)) return false;
        continue;
      }
    }
    if (!(c.regions[k]->side(p, k == 0 ? L.normal_first : L.normal_second).signed_distance > 0)) return false;
  }
  return true;
}

// Runs of points along a boundary (kBoundaryBand) met while clipping, for the warning.
struct AlongBoundary {
  int runs = 0;
  double max_gap = 0;  // largest |phi| of a point of such a run (model length)
  int region = -1;
  double off_surface = 0;  // largest gap beyond the band of a crossing with an edge off its surface
  int off_region = -1;
};

// phi at x and the region that attains it.
struct Phi {
  double value = std::numeric_limits<double>::infinity();
  double gap = 0;  // |p - nearest boundary point| of that region
  int region = -1;
};

Phi phi(const Clipper& c, const VecX& x) {
  const Linearization L = c.problem.linearize(x);
  const Vec3 p = c.problem.point(x);
  Phi out;
  for (int k = 0; k < 2; ++k) {
    if (!c.regions[static_cast<std::size_t>(k)]) continue;
    const FaceRegion::Side s = c.regions[static_cast<std::size_t>(k)]->side(p, k == 0 ? L.normal_first : L.normal_second);
    if (s.signed_distance < out.value) out = {s.signed_distance, (p - s.nearest).norm(), k};
  }
  return out;
}

// The curve's point at x (on both surfaces), its unit tangent n1 x n2 turned along `travel`
// (`fallback` where the normals are parallel).
CurvePoint curve_point(const Clipper& c, const VecX& x, const Vec3& travel, const Vec3& fallback) {
  const Linearization L = c.problem.linearize(x);
  Vec3 t = L.normal_first.cross(L.normal_second);
  if (t.dot(travel) < 0) t = -t;
  return CurvePoint{c.problem.wrap(x), c.problem.point(x), t.norm() > 0 ? Vec3(t.normalized()) : fallback};
}

// The curve point between a and b (a inside, b outside, or the reverse) where phi = 0: Illinois
// regula falsi in s, each trial point the curve's point where the unknown i that changes most
// between a and b takes a.x[i] + s (b.x[i] - a.x[i]). Empty when a trial point cannot be
// corrected or phi does not vanish there (its sign changed across a jump of the nearest
// boundary part, not across the boundary).
std::optional<CurvePoint> crossing(const Clipper& c, const CurvePoint& a, const CurvePoint& b, double fa, double fb,
                                   int* region, double* gap) {
  const VecX dx = c.problem.difference(a.x, b.x);
  Eigen::Index i = 0;
  dx.cwiseAbs().maxCoeff(&i);
  VecX x_best;
  Phi best;
  auto trial = [&](double s) -> std::optional<double> {
    const CorrectorResult r = solve_with_fixed_unknown(c.problem, a.x + s * dx, static_cast<int>(i), a.x[i] + s * dx[i], c.corrector);
    if (r.status != CorrectorStatus::kConverged) return std::nullopt;
    const Phi f = phi(c, r.x);
    if (!(std::abs(f.value) >= std::abs(best.value))) {
      best = f;
      x_best = r.x;
    }
    return f.value;
  };
  const double tol = kCrossingAccuracy * c.scale;
  double s0 = 0, s1 = 1, f0 = fa, f1 = fb;
  for (int it = 0; it < 200 && std::abs(best.value) > tol && std::abs(s1 - s0) > 1e-17; ++it) {
    const double s = std::clamp(s1 - f1 * (s1 - s0) / (f1 - f0), std::min(s0, s1), std::max(s0, s1));
    const auto f = trial(s);
    if (!f) return std::nullopt;
    if ((*f > 0) == (f1 > 0)) {
      f0 /= 2;  // Illinois: the end kept twice has its value halved
    } else {
      s0 = s1;
      f0 = f1;
    }
    s1 = s;
    f1 = *f;
  }
  // The gap to the edge curve is the model's own accuracy where its edges lie off its surfaces
  // (Ventilator.stp: 1.4e-5 and 1.2e-3 of a model of 88; refusing them dropped whole curves that
  // start outside a face and enter it): up to the band, or twice the largest gap of the region's
  // boundary samples. A sign change of phi away from the boundary (beyond a corner, where the
  // nearest boundary point is the vertex) has a gap of the order of its distance to the face.
  double allowed = std::max(1e3 * tol, kBoundaryBand * c.scale);
  if (best.region >= 0 && c.loops[static_cast<std::size_t>(best.region)])
    allowed = std::max(allowed, 2 * c.loops[static_cast<std::size_t>(best.region)]->edge_gap());
  if (!(std::abs(best.value) <= 1e3 * tol && best.gap <= allowed)) return std::nullopt;
  *region = best.region;
  *gap = best.gap;
  return curve_point(c, x_best, b.p - a.p, a.t);
}

// The curve's point on the plane across the chord a -> b at chord parameter t, and the chord
// parameter it has (empty where the corrector does not converge).
std::optional<std::pair<CurvePoint, double>> point_across_chord(const Clipper& c, const CurvePoint& a,
                                                                const CurvePoint& b, double t) {
  const Vec3 d = b.p - a.p;
  const Vec3 normal = d.normalized();
  const CorrectorResult r =
      solve_on_plane(c.problem, a.x + t * c.problem.difference(a.x, b.x), normal, normal.dot(a.p + t * d), c.corrector);
  if (r.status != CorrectorStatus::kConverged) return std::nullopt;
  const CurvePoint p = curve_point(c, r.x, d, a.t);
  return std::pair{p, (p.p - a.p).dot(d) / d.squaredNorm()};
}

// A traced curve with curve points added at and around the boundary points (edge_surface_points)
// that fall between two traced points; at_boundary marks the points added at boundary points.
struct WithBoundaryPoints {
  TracedCurve curve;
  std::vector<bool> at_boundary;
};

// Each boundary point q between two traced points gets the curve's point at q itself (q is on
// both surfaces and on the edge, so the plane across the chord through q meets the curve there)
// and points halfway to its neighbours (the next boundary point or the segment's end), so that
// each crossing shows as a change of side between consecutive points: a curve that enters and
// leaves a hole, or cuts a face's corner, within one step (issue 28 item 2), and a run along an
// edge ends at the edge's end. q belongs to the segment (a, b) whose chord is nearest to it,
// within a quarter of the chord (a step turns the tangent by less than a radian, so its sagitta
// is below chord / 8) or the band; its place is its projection on the chord.
WithBoundaryPoints with_boundary_points(const Clipper& c, const TracedCurve& curve,
                                        const std::vector<Vec3>& boundary_points) {
  const std::size_t n = curve.points.size();
  WithBoundaryPoints out{curve, std::vector<bool>(n, false)};
  if (boundary_points.empty() || n < 2) return out;
  const double band = kBoundaryBand * c.scale;
  std::vector<std::vector<double>> at(n - 1);  // chord parameters of the boundary points per segment
  for (const Vec3& q : boundary_points) {
    double best = std::numeric_limits<double>::infinity(), best_t = 0;
    std::size_t best_i = n;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const Vec3 a = curve.points[i].p, d = curve.points[i + 1].p - a;
      if (!(d.squaredNorm() > 0)) continue;
      const double t = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const double dist = (a + t * d - q).norm();
      if (dist < best && dist <= 0.25 * d.norm() + band) best = dist, best_t = t, best_i = i;
    }
    // At a traced point (within the band of it) the point itself shows the crossing.
    if (best_i < n && (q - curve.points[best_i].p).norm() > band && (q - curve.points[best_i + 1].p).norm() > band)
      at[best_i].push_back(best_t);
  }
  out.curve.points.clear();
  out.curve.segment_lengths.clear();
  out.at_boundary.clear();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    out.curve.points.push_back(curve.points[i]);
    out.at_boundary.push_back(false);
    std::vector<double>& t = at[i];
    if (t.empty()) continue;
    std::sort(t.begin(), t.end());
    std::vector<std::pair<double, bool>> targets;  // chord parameter, at a boundary point
    for (std::size_t k = 0; k <= t.size(); ++k) {
      targets.emplace_back(0.5 * ((k == 0 ? 0.0 : t[k - 1]) + (k == t.size() ? 1.0 : t[k])), false);
      if (k < t.size()) targets.emplace_back(t[k], true);
    }
    double last = 0;
    for (const auto& [target, on_edge] : targets) {
      const auto p = point_across_chord(c, curve.points[i], curve.points[i + 1], target);
      // Not within the band of its neighbours: two such points in a row read as a run along the boundary.
      if (!p || !(p->second > last && p->second < 1) || (p->first.p - out.curve.points.back().p).norm() <= band ||
          (p->first.p - curve.points[i + 1].p).norm() <= band)
        continue;
      out.curve.points.push_back(p->first);
      out.at_boundary.push_back(on_edge);
      last = p->second;
    }
  }
  out.curve.points.push_back(curve.points.back());
  out.at_boundary.push_back(false);
  return out;
}

// A piece's segments measured as trace_all measures a curve's (march/refined_arc_length.hpp);
// a piece of a curve of tangential contact by its points alone.
void measure(const Clipper& c, TracedCurve* piece) {
  piece->length = 0;
  piece->segment_lengths.clear();
  if (piece->tangential_contact) {
    for (std::size_t i = 0; i + 1 < piece->points.size(); ++i)
      piece->length +=
          arc_length_estimate(piece->points[i].p, piece->points[i].t, piece->points[i + 1].p, piece->points[i + 1].t);
    piece->length += arc_length_shortfall(piece->points, false);
    return;
  }
  piece->segment_lengths = segment_lengths(c.problem, piece->points, false, c.corrector);
  for (double l : piece->segment_lengths) piece->length += l;
}

// A point of the curve with where it stands, and at crossings the boundary point itself.
struct Marked {
  CurvePoint point;
  bool inside = false;
  bool boundary = false;  // an exact crossing point
  int region = -1;
};

// Sets f to +|f| (inside) on every run of two or more points within the boundary band that has
// a point outside (or on) the boundary.
void keep_runs_along_boundary(const Clipper& c, const std::vector<Phi>& at, const std::vector<bool>& at_boundary,
                              std::vector<double>* f, AlongBoundary* along) {
  const double band = kBoundaryBand * c.scale;
  std::size_t i = 0;
  while (i < at.size()) {
    std::size_t j = i;
    while (j < at.size() && std::abs(at[j].value) <= band) ++j;
    // Only a run with a point outside is decided by the band (one wholly inside is kept anyway).
    const bool decided =
        std::any_of(at.begin() + static_cast<std::ptrdiff_t>(i), at.begin() + static_cast<std::ptrdiff_t>(j),
                    [](const Phi& p) { return !(p.value > 0); });
    // Points added at boundary points lie in the band by construction: only traced ones make a run.
    const auto traced = std::count(at_boundary.begin() + static_cast<std::ptrdiff_t>(i),
                                   at_boundary.begin() + static_cast<std::ptrdiff_t>(j), false);
    if (traced >= 2 && decided) {
      ++along->runs;
      for (std::size_t k = i; k < j; ++k) {
        (*f)[k] = std::max(std::abs(at[k].value), std::numeric_limits<double>::min());
        if (std::abs(at[k].value) >= along->max_gap)
          along->max_gap = std::abs(at[k].value), along->region = at[k].region;
      }
    }
    i = std::max(j, i + 1);
  }
}

// Traced points on the boundary itself, to kCrossingAccuracy (a curve ending where the face
// ends, the rim of a cylinder face; a crossing at a traced point), alone in the band (a run of
// two or more is keep_runs_along_boundary's): their sign says nothing, so each takes its
// neighbours' side, and one between two different sides is the crossing. Returns the crossings;
// f is changed so that no sign change is seen next to them.
std::vector<bool> traced_crossings(const Clipper& c, const TracedCurve& curve, const std::vector<Phi>& at,
                                   std::vector<double>* f) {
  const std::size_t n = f->size();
  const double on = kCrossingAccuracy * c.scale, band = kBoundaryBand * c.scale;
  std::vector<bool> out(n, false);
  const auto m = static_cast<std::ptrdiff_t>(n);
  auto index = [&](std::ptrdiff_t k) -> std::optional<std::size_t> {  // a closed curve wraps
    if (curve.closed) k = (k % (m - 1) + (m - 1)) % (m - 1);
    if (k < 0 || k >= m) return std::nullopt;
    return static_cast<std::size_t>(k);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!(std::abs(at[i].value) <= on)) continue;
    const auto k = static_cast<std::ptrdiff_t>(i);
    const std::optional<std::size_t> before = index(k - 1), after = index(k + 1);
    if ((before && std::abs(at[*before].value) <= band) || (after && std::abs(at[*after].value) <= band)) continue;
    out[i] = before && after && ((*f)[*before] > 0) != ((*f)[*after] > 0);
    const double kept = after ? (*f)[*after] : before ? (*f)[*before] : (*f)[i];
    (*f)[i] = std::copysign(std::numeric_limits<double>::min(), kept);
  }
  return out;
}

// The points of curve `curve` with the crossings inserted (a closed curve rotated to start at
// its first crossing, and then open). *crossings counts them; runs along a boundary go to *along.
std::vector<Marked> mark(const Clipper& c, const TracedCurve& curve, const std::vector<bool>& at_boundary,
                         int* crossings, AlongBoundary* along) {
  std::vector<Marked> out;
  std::vector<Phi> at;
  std::vector<double> f;
  for (const CurvePoint& p : curve.points) {
    at.push_back(phi(c, p.x));
    f.push_back(at.back().value);
  }
  keep_runs_along_boundary(c, at, at_boundary, &f, along);
  const std::vector<bool> on_boundary = traced_crossings(c, curve, at, &f);
  // The first point's side starts the count: far from the boundary it is taken in the parameter
  // planes (the 3D sign there is that of whatever edge is nearest).
  if (far_from_boundary(c, at.front().value)) {
    const bool in = inside_far(c, curve.points.front().p, curve.points.front().x);
    f.front() = in ? std::abs(f.front()) : -std::abs(f.front());
    if (curve.closed) f.back() = f.front();
  }
  bool inside = f.front() > 0;
  *crossings = 0;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    if (on_boundary[i]) {
      out.push_back({curve.points[i], false, true, at[i].region});
      inside = f[i] > 0;
      ++*crossings;
      continue;
    }
    if (i > 0 && !on_boundary[i - 1] && (f[i] > 0) != (f[i - 1] > 0)) {
      int region = -1;
      double gap = 0;
      if (auto x = crossing(c, curve.points[i - 1], curve.points[i], f[i - 1], f[i], &region, &gap)) {
        out.push_back({*x, true, true, region});
        if (gap > kBoundaryBand * c.scale && gap > along->off_surface)
          along->off_surface = gap, along->off_region = region;
        inside = f[i] > 0;
        ++*crossings;
      }
    }
    out.push_back({curve.points[i], inside, false, -1});
  }
  if (!curve.closed || *crossings == 0) return out;
  // Closed: the last point is the first; start at the first crossing and go round once.
  out.pop_back();
  const auto first = std::find_if(out.begin(), out.end(), [](const Marked& m) { return m.boundary; });
  std::rotate(out.begin(), first, out.end());
  out.push_back(out.front());
  return out;
}

std::string end_message(const Clipper& c, int region) {
  return "on the boundary of " + c.regions[static_cast<std::size_t>(region)]->name();
}

// The pieces of one curve inside the regions; each piece's first point index in the input curve
// is not kept (pieces are new curves).
std::vector<TracedCurve> pieces(const Clipper& c, const TracedCurve& curve, const std::vector<bool>& at_boundary,
                                AlongBoundary* along) {
  int crossings = 0;
  const std::vector<Marked> m = mark(c, curve, at_boundary, &crossings, along);
  if (crossings == 0) return m.front().inside ? std::vector<TracedCurve>{curve} : std::vector<TracedCurve>{};
  std::vector<TracedCurve> out;
  TracedCurve piece;
  bool open = false;
  auto finish = [&](Termination end, const std::string& message) {
    piece.end_end = end;
    piece.end_message = message;
    piece.closed = false;
    measure(c, &piece);
    if (piece.points.size() >= 2) out.push_back(piece);
    piece = TracedCurve{};
    piece.tangential_contact = curve.tangential_contact;
    open = false;
  };
  piece.tangential_contact = curve.tangential_contact;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const Marked& p = m[k];
    if (p.boundary) {
      if (open) {
        piece.points.push_back(p.point);
        finish(Termination::kLeftDomain, end_message(c, p.region));
      }
      // Entering when the next point is inside.
      if (k + 1 < m.size() && m[k + 1].inside && !m[k + 1].boundary) {
        piece.points.push_back(p.point);
        piece.start_end = Termination::kLeftDomain;
        piece.start_message = end_message(c, p.region);
        open = true;
      }
      continue;
    }
    if (!p.inside) continue;
    if (!open) {  // an open curve's first point inside: the piece keeps the curve's own start
      piece.start_end = curve.start_end;
      piece.start_message = curve.start_message;
      open = true;
    }
    piece.points.push_back(p.point);
  }
  if (open) finish(curve.end_end, curve.end_message);
  return out;
}

// The parameter of the conic's point nearest p: the nearest of 256 samples of its range, then
// Gauss-Newton on (k(t) - p) . k'(t) = 0.
double conic_parameter(const Conic& k, const Vec3& p) {
  double best = k.range.lo, dmin = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 256; ++i) {
    const double t = k.range.lo + k.range.width() * i / 256;
    const double d = (k.point(t) - p).norm();
    if (d < dmin) {
      dmin = d;
      best = t;
    }
  }
  for (int it = 0; it < 50; ++it) {
    const Vec3 d = k.derivative(best);
    if (!(d.squaredNorm() > 0)) break;
    const double step = (k.point(best) - p).dot(d) / d.squaredNorm();
    best -= step;
    if (std::abs(step) <= 1e-16 * (1 + std::abs(best))) break;
  }
  return best;
}

// The conic of a piece of its curve: the same conic, its range from the piece's ends in the
// piece's direction of travel (a periodic conic's range may pass 2 pi).
Conic conic_piece(const Conic& k, const TracedCurve& piece) {
  Conic out = k;
  double t0 = conic_parameter(k, piece.points.front().p), t1 = conic_parameter(k, piece.points.back().p);
  const bool increasing = k.derivative(t0).dot(piece.points.front().t) >= 0;
  if (!increasing) std::swap(t0, t1);
  if (k.periodic())
    while (t1 <= t0) t1 += 2 * std::numbers::pi;
  out.range = {std::min(t0, t1), std::max(t0, t1)};
  return out;
}

}  // namespace

void clip_to_regions(const std::array<const FaceRegion*, 2>& regions, IntersectionRun* run) {
  if (!regions[0] && !regions[1]) return;
  const Problem& P = run->problem;
  Clipper c{P, regions, CorrectorOptions{run->used.options.tolerance, 20}, P.scale(), {}};
  for (std::size_t k = 0; k < 2; ++k)
    if (regions[k] &&
        !(run->result.curves.empty() && run->result.singular_points.empty() && run->result.isolated_points.empty()))
      c.loops[k] = ParameterLoops::build(*regions[k], k == 0 ? P.first() : P.second());
  std::vector<Vec3> boundary_points;
  const EdgeSurfaceTolerances edge{run->used.options.tolerance, kBoundaryBand * c.scale};
  for (std::size_t k = 0; k < 2; ++k)
    if (regions[k] && !run->result.curves.empty()) {
      const std::vector<Vec3> on = edge_surface_points(*regions[k], k == 0 ? P.second() : P.first(), edge);
      boundary_points.insert(boundary_points.end(), on.begin(), on.end());
    }
  std::vector<TracedCurve> kept;
  std::vector<Conic> conics;
  std::vector<std::vector<int>> new_index(run->result.curves.size());
  AlongBoundary along;
  for (std::size_t i = 0; i < run->result.curves.size(); ++i) {
    const WithBoundaryPoints with = with_boundary_points(c, run->result.curves[i], boundary_points);
    for (TracedCurve& piece : pieces(c, with.curve, with.at_boundary, &along)) {
      new_index[i].push_back(static_cast<int>(kept.size()));
      if (i < run->conics.size()) {
        conics.push_back(conic_piece(run->conics[i], piece));
        piece.length = conic_length(conics.back());  // exact, as the closed form's own pieces
      }
      kept.push_back(std::move(piece));
    }
  }
  run->result.curves = std::move(kept);
  if (!run->conics.empty()) run->conics = std::move(conics);
  if (along.runs > 0) {
    run->result.start_search.certified = false;
    std::ostringstream w;
    w.precision(3);
    w << along.runs << " stretch(es) of curve run along the boundary of "
      << regions[static_cast<std::size_t>(along.region)]->name() << ", within " << along.max_gap
      << " of it (the band is " << kBoundaryBand << " times the model size, " << kBoundaryBand * c.scale
      << "): kept as on the closed face, which that band decides, not certified";
    run->result.warnings.push_back(w.str());
  }
  if (along.off_region >= 0) {
    run->result.start_search.certified = false;
    std::ostringstream w;
    w.precision(3);
    w << "the boundary of " << regions[static_cast<std::size_t>(along.off_region)]->name() << " lies up to "
      << along.off_surface << " off its surface (beyond the band, " << kBoundaryBand * c.scale
      << "): the curve is cut where it passes the boundary, to the model's accuracy, not certified";
    run->result.warnings.push_back(w.str());
  }
  // Singular and isolated points: kept inside the regions, curve indices renumbered (a curve
  // cut into pieces is listed by each piece).
  auto inside = [&](const SingularPointReport& s) {
    const double f = phi(c, s.x).value;
    return far_from_boundary(c, f) ? inside_far(c, s.p, s.x) : f >= -1e-9 * c.scale;
  };
  for (auto* list : {&run->result.singular_points, &run->result.isolated_points}) {
    std::vector<SingularPointReport> keep;
    for (SingularPointReport& s : *list) {
      if (!inside(s)) continue;
      std::vector<int> curves;  // the pieces of its curves that pass it
      for (int old : s.curves)
        if (old >= 0 && static_cast<std::size_t>(old) < new_index.size())
          for (int k : new_index[static_cast<std::size_t>(old)])
            for (const CurvePoint& q : run->result.curves[static_cast<std::size_t>(k)].points)
              if ((q.p - s.p).norm() <= 1e-9 * c.scale) {
                curves.push_back(k);
                break;
              }
      s.curves = curves;
      keep.push_back(std::move(s));
    }
    *list = std::move(keep);
  }
}

}  // namespace ssimarch
