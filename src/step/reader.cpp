// STEP faces and surfaces -> ssimarch surfaces (ISO 10303-42 §4.4 geometry: the surfaces'
// parameterisations below are the standard's, which are those of surface/'s primitives).
#include "ssimarch/step/reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "ssimarch/core/text_file.hpp"
#include "ssimarch/surface/frame.hpp"
#include "access.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch {

using internal::cat;
using internal::StepAccess;
using internal::StepPlacement;

namespace {

bool is_face(const StepInstance& inst) {
  const std::string& t = inst.records.front().type;
  return inst.records.size() == 1 && (t == "ADVANCED_FACE" || t == "FACE_SURFACE");
}

// The surface's name for listings: the defining entity of a complex B-spline instance.
std::string surface_type_of(const StepInstance& s) {
  for (const char* t : {"RATIONAL_B_SPLINE_SURFACE", "B_SPLINE_SURFACE_WITH_KNOTS", "BEZIER_SURFACE"})
    if (s.records.size() > 1 && s.record(t)) return t;
  return s.type_text();
}

// Where the parameters of a surface are bounded: a face's boundary points, or the rectangle of
// a RECTANGULAR_TRIMMED_SURFACE (u1, u2, v1, v2).
struct Trim {
  std::vector<Vec3> boundary;
  std::optional<std::array<double, 4>> rectangle;
};

// The interval of the coordinate `axis` (0, 1, 2 of a frame's local coordinates) over the
// boundary points, or the rectangle's side (a length: a plane's u and v, a cylinder's or cone's v,
// in the file's unit, hence scaled); fails for neither.
Interval trimmed(const StepAccess& a, const StepInstance& s, const Trim& trim, const Frame& f, int axis, int side) {
  if (trim.rectangle) {
    const auto& r = *trim.rectangle;
    const double lo = std::min(r[2 * side], r[2 * side + 1]), hi = std::max(r[2 * side], r[2 * side + 1]);
    return {lo * a.scale(), hi * a.scale()};
  }
  if (trim.boundary.empty())
    a.fail(s, "is unbounded: select a face whose boundary bounds it, or wrap it in a RECTANGULAR_TRIMMED_SURFACE");
  Interval i{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Vec3& p : trim.boundary) {
    const double x = (p - f.origin).dot(axis == 0 ? f.e0 : axis == 1 ? f.e1 : f.e2);
    i.lo = std::min(i.lo, x);
    i.hi = std::max(i.hi, x);
  }
  return i;
}

template <class Make>
Surface checked(const StepAccess& a, const StepInstance& s, Make make) {
  try {
    return Surface(make());
  } catch (const InputError& e) {
    a.fail(s, e.message());
  }
}

Surface elementary(const StepAccess& a, const StepInstance& s, const Trim& trim, double angle_unit) {
  const StepRecord& r = s.records.front();
  const StepPlacement p = internal::step_placement(a, a.ref(s, a.param(s, r, 1, "position"), "position"));
  const Frame f = Frame::from_axis(p.origin, p.axis, p.reference, a.file().where(s));
  auto length = [&](std::size_t k, const char* what) { return a.length(s, a.param(s, r, k, what), what); };
  if (r.type == "PLANE") {
    const ParamDomain d{trimmed(a, s, trim, f, 0, 0), trimmed(a, s, trim, f, 1, 1)};
    return checked(a, s, [&] { return Plane(p.origin, p.axis, d, p.reference); });
  }
  if (r.type == "CYLINDRICAL_SURFACE") {
    const double radius = length(2, "radius");
    const Interval v = trimmed(a, s, trim, f, 2, 1);
    return checked(a, s, [&] { return Cylinder(p.origin, p.axis, radius, v, p.reference); });
  }
  if (r.type == "CONICAL_SURFACE") {
    // STEP: radius R at v = 0, v along the axis from the placement; ours: v from the apex.
    const double radius = length(2, "radius"),
                 alpha = a.number(s, a.param(s, r, 3, "semi_angle"), "semi_angle") * angle_unit;
    if (!(alpha > 0 && alpha < std::numbers::pi / 2)) a.fail(s, "semi_angle must be in (0, 90) degrees");
    const double shift = radius / std::tan(alpha);
    const Vec3 apex = f.to_world(0.0, 0.0, -shift);
    Interval v = trimmed(a, s, trim, f, 2, 1);
    v = {v.lo + shift, v.hi + shift};
    return checked(a, s, [&] { return Cone(apex, p.axis, alpha, v, p.reference); });
  }
  if (r.type == "SPHERICAL_SURFACE") {
    const double radius = length(2, "radius");
    return checked(a, s, [&] { return Sphere(p.origin, radius, p.axis, p.reference); });
  }
  const double major = length(2, "major_radius"), minor = length(3, "minor_radius");
  return checked(a, s, [&] { return Torus(p.origin, p.axis, major, minor, p.reference); });
}

// Knots from distinct values and multiplicities, at most `expected` of them.
std::vector<double> expand_knots(const StepAccess& a, const StepInstance& s, const StepValue& mults,
                                 const StepValue& values, std::size_t expected) {
  const std::vector<double> m = a.numbers(s, mults, "knot multiplicities"), k = a.numbers(s, values, "knots");
  if (m.size() != k.size()) a.fail(s, cat("has ", m.size(), " multiplicities for ", k.size(), " knots"));
  std::vector<double> out;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!(m[i] >= 1 && m[i] == std::floor(m[i]) && out.size() + static_cast<std::size_t>(m[i]) <= expected))
      a.fail(s, cat("knot multiplicities must be integers >= 1 adding up to ", expected,
                    " (control points + degree + 1)"));
    out.insert(out.end(), static_cast<std::size_t>(m[i]), k[i]);
  }
  if (out.size() != expected)
    a.fail(s, cat("knot multiplicities add up to ", out.size(), ", not ", expected, " (control points + degree + 1)"));
  return out;
}

std::vector<double> bezier_knots(int degree) {
  std::vector<double> k(static_cast<std::size_t>(degree) + 1, 0.0);
  k.resize(2 * k.size(), 1.0);
  return k;
}

// B_SPLINE_SURFACE_WITH_KNOTS and BEZIER_SURFACE, simple or in a complex instance with
// RATIONAL_B_SPLINE_SURFACE (ISO 10303-42 §4.4.16-4.4.20).
SplineSurfaceData spline_data(const StepAccess& a, const StepInstance& s) {
  const StepRecord* base = s.record("B_SPLINE_SURFACE");
  const std::size_t o = base ? 0 : 1;  // a simple instance starts with its name
  const StepRecord& b = base ? *base : s.records.front();
  SplineSurfaceData d;
  d.degree_u = a.integer(s, a.param(s, b, o, "u_degree"), "u_degree", 1, 64);
  d.degree_v = a.integer(s, a.param(s, b, o + 1, "v_degree"), "v_degree", 1, 64);
  for (const StepValue& row : a.list(s, a.param(s, b, o + 2, "control_points_list"), "control_points_list")) {
    d.points.emplace_back();
    for (const StepValue& v : a.list(s, row, "a row of control points"))
      d.points.back().push_back(a.point(s, v, "control point"));
  }
  if (d.points.empty() || d.points[0].empty()) a.fail(s, "has no control points");
  const std::size_t nu = d.points.size(), nv = d.points[0].size();
  if (s.record("BEZIER_SURFACE")) {
    d.knots_u = bezier_knots(d.degree_u);
    d.knots_v = bezier_knots(d.degree_v);
  } else {
    const StepRecord& k = base ? a.record(s, "B_SPLINE_SURFACE_WITH_KNOTS") : b;
    const std::size_t ko = base ? 0 : 8;
    d.knots_u = expand_knots(a, s, a.param(s, k, ko, "u_multiplicities"), a.param(s, k, ko + 2, "u_knots"),
                             nu + d.degree_u + 1);
    d.knots_v = expand_knots(a, s, a.param(s, k, ko + 1, "v_multiplicities"), a.param(s, k, ko + 3, "v_knots"),
                             nv + d.degree_v + 1);
  }
  if (const StepRecord* rat = s.record("RATIONAL_B_SPLINE_SURFACE"))
    for (const StepValue& row : a.list(s, a.param(s, *rat, 0, "weights_data"), "weights_data"))
      d.weights.push_back(a.numbers(s, row, "weights"));
  return d;
}

Surface spline_surface(const StepAccess& a, const StepInstance& s) {
  const SplineSurfaceData d = spline_data(a, s);
  return checked(a, s, [&] {
    return BSplineSurface(d.degree_u, d.degree_v, d.knots_u, d.knots_v, d.points, d.weights, a.file().where(s));
  });
}

bool is_spline(const StepInstance& s) { return s.record("B_SPLINE_SURFACE_WITH_KNOTS") || s.record("BEZIER_SURFACE"); }

Surface any_surface(const StepAccess& a, const StepInstance& s, Trim trim, double angle_unit) {
  const std::string& t = s.records.front().type;
  if (s.records.size() == 1 && (t == "PLANE" || t == "CYLINDRICAL_SURFACE" || t == "CONICAL_SURFACE" ||
                                t == "SPHERICAL_SURFACE" || t == "TOROIDAL_SURFACE"))
    return elementary(a, s, trim, angle_unit);
  if (is_spline(s)) return spline_surface(a, s);
  std::optional<Interval> v_range;
  if (trim.rectangle)
    v_range = Interval{std::min((*trim.rectangle)[2], (*trim.rectangle)[3]),
                       std::max((*trim.rectangle)[2], (*trim.rectangle)[3])};
  if (const auto swept = internal::step_swept_surface(a, s, trim.boundary, v_range))
    return checked(a, s, [&] {
      return BSplineSurface(swept->degree_u, swept->degree_v, swept->knots_u, swept->knots_v, swept->points,
                            swept->weights, a.file().where(s));
    });
  if (s.records.size() == 1 && t == "OFFSET_SURFACE") {
    const StepRecord& r = s.records.front();
    const StepInstance& basis = a.ref(s, a.param(s, r, 1, "basis_surface"), "basis_surface");
    if (&basis == &s) a.fail(s, "offsets itself");
    if (basis.records.front().type == "OFFSET_SURFACE") a.fail(s, "offsets an offset surface");
    const double d = a.length(s, a.param(s, r, 2, "distance"), "distance");
    return internal::step_offset_surface(any_surface(a, basis, trim, angle_unit), d, a, s);
  }
  if (s.records.size() == 1 && t == "RECTANGULAR_TRIMMED_SURFACE") {
    const StepRecord& r = s.records.front();
    std::array<double, 4> rect{};
    for (std::size_t k = 0; k < 4; ++k) rect[k] = a.number(s, a.param(s, r, 2 + k, "trim parameter"), "trim parameter");
    const StepInstance& basis = a.ref(s, r.params[1], "basis_surface");
    if (&basis == &s) a.fail(s, "trims itself");
    if (basis.records.front().type == "RECTANGULAR_TRIMMED_SURFACE") a.fail(s, "trims a trimmed surface");
    return any_surface(a, basis, Trim{{}, rect}, angle_unit);
  }
  a.fail(s,
         "is not a surface type this reader knows (PLANE, CYLINDRICAL_SURFACE, CONICAL_SURFACE, "
         "SPHERICAL_SURFACE, TOROIDAL_SURFACE, B_SPLINE_SURFACE_WITH_KNOTS, BEZIER_SURFACE, rational ones, "
         "SURFACE_OF_LINEAR_EXTRUSION, SURFACE_OF_REVOLUTION, OFFSET_SURFACE of an elementary surface, "
         "RECTANGULAR_TRIMMED_SURFACE)");
}

// Radians per plane-angle unit: a CONVERSION_BASED_UNIT with PLANE_ANGLE_UNIT (ISO 10303-41)
// whose factor is a PLANE_ANGLE_MEASURE_WITH_UNIT in radians, e.g. 0.0174532925 for degrees.
double plane_angle_unit(const StepAccess& a) {
  for (std::int64_t id : a.file().order) {
    const StepInstance& u = *a.file().find(id);
    const StepRecord* conv = u.record("CONVERSION_BASED_UNIT");
    if (!conv || !u.record("PLANE_ANGLE_UNIT")) continue;
    const StepInstance& m = a.ref(u, a.param(u, *conv, 1, "conversion_factor"), "conversion_factor");
    const double f = a.number(m, a.param(m, m.records.front(), 0, "value_component"), "value_component");
    if (!(f > 0)) a.fail(m, "an angle unit must be > 0");
    return f;
  }
  return 1.0;
}

}  // namespace

StepModel::StepModel(StepFile file, const std::optional<StepLengthUnit>& unit) : file_(std::move(file)) {
  // A malformed unit stops a conversion, not a reading in the file's own numbers (`faces`
  // reports it: step_length_unit).
  if (unit) {
    file_unit_ = step_length_unit(file_);
    scale_ = length_conversion(file_unit_, *unit, file_.source);
    unit_ = *unit;
    converted_to_ = unit;
  } else {
    try {
      file_unit_ = unit_ = step_length_unit(file_);
    } catch (const InputError&) {
      file_unit_ = unit_ = StepLengthUnit{};
    }
  }
  const StepAccess a(file_, {}, scale_);
  angle_unit_ = plane_angle_unit(a);
  solids_ = internal::solids_of_faces(a);
  for (const internal::PlacedFace& placed : internal::placed_faces(a)) {
    const StepInstance& f = *file_.find(placed.face);
    const StepRecord& r = f.records.front();
    const StepInstance& s = a.ref(f, a.param(f, r, 2, "face_geometry"), "face_geometry");
    faces_.push_back({static_cast<int>(faces_.size()) + 1, placed.face, s.id, f.line, surface_type_of(s),
                      a.boolean(f, a.param(f, r, 3, "same_sense"), "same_sense"), placed.placement, placed.instance});
  }
}

StepModel StepModel::read(const std::filesystem::path& path, const InputLimits& limits,
                          const std::optional<StepLengthUnit>& unit) {
  return StepModel(read_step_file(path, limits), unit);
}

const StepFace& StepModel::face(int index, const std::string& where) const {
  if (index < 1 || static_cast<std::size_t>(index) > faces_.size())
    throw InputError(where, cat("face ", index, " does not exist: ", file_.source, " has ", faces_.size(),
                                " faces, numbered from 1"));
  return faces_[static_cast<std::size_t>(index) - 1];
}

Surface StepModel::surface(std::int64_t entity, const PartPlacement& placement) const {
  const StepInstance* inst = file_.find(entity);
  if (!inst) throw InputError(file_.source, cat("has no instance #", entity));
  const StepAccess a(file_, placement, scale_);
  if (!is_face(*inst)) return any_surface(a, *inst, {}, angle_unit_);
  const StepInstance& s = a.ref(*inst, inst->records.front().params.at(2), "face_geometry");
  return any_surface(a, s, Trim{internal::step_boundary_points(a, *inst), std::nullopt}, angle_unit_);
}

std::optional<SplineSurfaceData> StepModel::spline_data(std::int64_t entity, const PartPlacement& placement) const {
  const StepInstance* inst = file_.find(entity);
  if (!inst) throw InputError(file_.source, cat("has no instance #", entity));
  const StepAccess a(file_, placement, scale_);
  const StepInstance* s = is_face(*inst) ? &a.ref(*inst, inst->records.front().params.at(2), "face_geometry") : inst;
  std::optional<Interval> v_range;
  if (s->records.size() == 1 && s->records.front().type == "RECTANGULAR_TRIMMED_SURFACE") {
    const StepRecord& r = s->records.front();
    const double v1 = a.number(*s, a.param(*s, r, 4, "v1"), "v1"), v2 = a.number(*s, a.param(*s, r, 5, "v2"), "v2");
    v_range = Interval{std::min(v1, v2), std::max(v1, v2)};
    s = &a.ref(*s, a.param(*s, r, 1, "basis_surface"), "basis_surface");
  }
  if (is_spline(*s)) return ::ssimarch::spline_data(a, *s);
  return internal::step_swept_surface(
      a, *s, is_face(*inst) ? internal::step_boundary_points(a, *inst) : std::vector<Vec3>{}, v_range);
}

std::shared_ptr<const FaceRegion> StepModel::face_region(std::int64_t entity, const PartPlacement& placement) const {
  const StepInstance* inst = file_.find(entity);
  if (!inst) throw InputError(file_.source, cat("has no instance #", entity));
  if (!is_face(*inst)) return nullptr;
  // The solid's key names the occurrence: the same solid placed twice is two solids, and the
  // same file read in two units two models.
  std::string solid;
  if (const auto it = solids_.find(entity); it != solids_.end()) {
    std::ostringstream key;
    key << std::hexfloat << file_.source << " #" << it->second << " x" << scale_ << " @";
    for (int i = 0; i < 9; ++i) key << ' ' << placement.rotation(i / 3, i % 3);
    for (int i = 0; i < 3; ++i) key << ' ' << placement.translation[i];
    solid = key.str();
  }
  return internal::step_face_region(StepAccess(file_, placement, scale_), *inst,
                                    cat("STEP face #", entity, " of ", file_.source), solid);
}

BSplineCurve StepModel::bspline_curve(std::int64_t entity) const {
  const StepInstance* c = file_.find(entity);
  if (!c) throw InputError(file_.source, cat("has no instance #", entity));
  const StepAccess a(file_);
  if (c->records.size() != 1 || c->records.front().type != "B_SPLINE_CURVE_WITH_KNOTS")
    a.fail(*c, "is not a (non-rational) B_SPLINE_CURVE_WITH_KNOTS");
  const StepRecord& r = c->records.front();
  BSplineCurve b;
  b.degree = a.integer(*c, a.param(*c, r, 1, "degree"), "degree", 1, 64);
  for (const StepValue& v : a.list(*c, a.param(*c, r, 2, "control_points_list"), "control_points_list")) {
    const StepInstance& pt = a.ref(*c, v, "control point");
    const std::vector<double> x =
        a.numbers(pt, a.param(pt, a.record(pt, "CARTESIAN_POINT"), 1, "coordinates"), "coordinates");
    if (!b.control_points.empty() && x.size() != static_cast<std::size_t>(b.control_points[0].size()))
      a.fail(pt, "has another dimension than the curve's first control point");
    // A 3D curve is in the model's unit; a 2D one lies in a surface's parameter space.
    const double scale = x.size() == 3 ? scale_ : 1.0;
    b.control_points.push_back(Eigen::Map<const VecX>(x.data(), static_cast<Eigen::Index>(x.size())) * scale);
  }
  if (b.control_points.size() < static_cast<std::size_t>(b.degree) + 1)
    a.fail(*c, "has fewer than degree + 1 control points");
  b.knots = expand_knots(a, *c, a.param(*c, r, 6, "knot_multiplicities"), a.param(*c, r, 7, "knots"),
                         b.control_points.size() + static_cast<std::size_t>(b.degree) + 1);
  for (std::size_t i = 1; i < b.knots.size(); ++i)
    if (!(b.knots[i] >= b.knots[i - 1])) a.fail(*c, "knots must not decrease");
  return b;
}

}  // namespace ssimarch
