#include "ssimarch/step/writer.hpp"

#include <charconv>
#include <map>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/surface/frame.hpp"

namespace ssimarch {

namespace {

// Strings are built by streams: GCC 12 warns falsely on chains of std::string + under -O3 (bug 105651).

// A REAL of ISO 10303-21 §6.3.2: digits, a decimal point, an optional exponent ("1.", "2.5E-09").
std::string step_real(double x) {
  char buf[64];
  const std::string s(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
  const std::size_t e = s.find('e');
  const std::string mantissa = s.substr(0, e);
  std::ostringstream o;
  o << mantissa << (mantissa.find('.') == std::string::npos ? "." : "");
  if (e != std::string::npos) o << 'E' << s.substr(e + 1);
  return o.str();
}

// A string of ISO 10303-21 §6.3.3 (apostrophes doubled).
std::string step_string(const std::string& s) {
  std::ostringstream o;
  o << '\'';
  for (char c : s) o << c << (c == '\'' ? "'" : "");
  o << '\'';
  return o.str();
}

class StepData {
 public:
  /// Appends "#id=PARTS...;" and returns id.
  template <class... Parts>
  int add(const Parts&... parts) {
    body_ << "#" << ++last_ << "=";
    (body_ << ... << parts);
    body_ << ";\n";
    return last_;
  }
  std::string text() const { return body_.str(); }

 private:
  std::ostringstream body_;
  int last_ = 0;
};

std::string ref(int id) {
  std::ostringstream o;
  o << '#' << id;
  return o.str();
}

template <class T, class F>
std::string list(const std::vector<T>& items, F text) {
  std::ostringstream o;
  o << '(';
  for (std::size_t i = 0; i < items.size(); ++i) o << (i ? "," : "") << text(items[i]);
  o << ')';
  return o.str();
}

std::string count(int m) { return std::to_string(m); }

int add_bspline(StepData* d, const std::string& name, const BSplineCurve& b) {
  std::vector<int> points;
  for (const VecX& c : b.control_points) {
    const std::vector<double> xs(c.data(), c.data() + c.size());
    std::ostringstream o;
    o << "CARTESIAN_POINT(''," << list(xs, step_real) << ")";
    points.push_back(d->add(o.str()));
  }
  std::vector<double> knots;
  std::vector<int> mults;
  b.distinct_knots(&knots, &mults);
  // closed_curve: periodic, or clamped with coinciding ends (a loop through a singular point).
  const bool closed = b.periodic || b.control_points.front() == b.control_points.back();
  std::ostringstream o;
  o << "B_SPLINE_CURVE_WITH_KNOTS(" << step_string(name) << "," << b.degree << "," << list(points, ref)
    << ",.UNSPECIFIED.," << (closed ? ".T." : ".F.") << ",.U.," << list(mults, count) << "," << list(knots, step_real)
    << ",.UNSPECIFIED.)";
  return d->add(o.str());
}

// Product, units and the two representation contexts; returns {3D context, 2D context, shape}.
std::array<int, 3> add_frame(StepData* d, double tolerance) {
  const int app = d->add("APPLICATION_CONTEXT('managed model based 3d engineering')");
  d->add("APPLICATION_PROTOCOL_DEFINITION('international standard','ap242_managed_model_based_3d_engineering',2014,",
         ref(app), ")");
  const int pc = d->add("PRODUCT_CONTEXT('',", ref(app), ",'mechanical')");
  const int product = d->add("PRODUCT('ssimarch','intersection curves','',", list(std::vector<int>{pc}, ref), ")");
  const int formation = d->add("PRODUCT_DEFINITION_FORMATION('','',", ref(product), ")");
  const int pdc = d->add("PRODUCT_DEFINITION_CONTEXT('part definition',", ref(app), ",'design')");
  const int pd = d->add("PRODUCT_DEFINITION('design','',", ref(formation), ",", ref(pdc), ")");
  const int shape = d->add("PRODUCT_DEFINITION_SHAPE('','',", ref(pd), ")");
  const int length = d->add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))");
  const int angle = d->add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))");
  const int solid = d->add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())");
  const int uncertainty = d->add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(", step_real(tolerance), "),",
                                 ref(length) + ",'distance_accuracy_value','largest max_deviation of the curves')");
  const int ctx3 = d->add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((",
                          ref(uncertainty) + "))GLOBAL_UNIT_ASSIGNED_CONTEXT((", ref(length), ",", ref(angle), ",",
                          ref(solid) + "))REPRESENTATION_CONTEXT('3D','model space'))");
  const int ctx2 = d->add(
      "(GEOMETRIC_REPRESENTATION_CONTEXT(2)PARAMETRIC_REPRESENTATION_CONTEXT()REPRESENTATION_CONTEXT("
      "'2D','parameter space'))");
  return {ctx3, ctx2, shape};
}

std::string reals(std::initializer_list<double> xs) { return list(std::vector<double>(xs), step_real); }

std::string vec3(const Vec3& v) { return reals({v.x(), v.y(), v.z()}); }

// AXIS2_PLACEMENT_3D of a primitive's frame: location, axis e2, reference direction e0.
int add_placement(StepData* d, const Frame& f) {
  const int o = d->add("CARTESIAN_POINT('',", vec3(f.origin), ")");
  const int z = d->add("DIRECTION('',", vec3(f.e2), ")");
  const int x = d->add("DIRECTION('',", vec3(f.e0), ")");
  return d->add("AXIS2_PLACEMENT_3D('',", ref(o), ",", ref(z), ",", ref(x), ")");
}

// A surface bounded to its domain (ISO 10303-42 §4.4.35): the parameters stay the basis's.
int add_trimmed(StepData* d, const std::string& name, int basis, const ParamDomain& dom) {
  std::ostringstream o;
  o << "RECTANGULAR_TRIMMED_SURFACE(" << step_string(name) << "," << ref(basis) << "," << step_real(dom.u.lo) << ","
    << step_real(dom.u.hi) << "," << step_real(dom.v.lo) << "," << step_real(dom.v.hi) << ",.T.,.T.)";
  return d->add(o.str());
}

// Knots as distinct values with multiplicities (STEP's form).
void distinct_knots(const std::vector<double>& knots, std::vector<double>* values, std::vector<int>* mults) {
  for (double k : knots) {
    if (!values->empty() && values->back() == k) {
      ++mults->back();
    } else {
      values->push_back(k);
      mults->push_back(1);
    }
  }
}

// B_SPLINE_SURFACE_WITH_KNOTS (ISO 10303-42 §4.4.17), or for a rational net the complex
// instance with RATIONAL_B_SPLINE_SURFACE (§4.4.20; records in alphabetical order, Part 21
// §11.2.5.3). Not closed, not periodic: ssimarch's spline surfaces are neither.
int add_spline_surface(StepData* d, const std::string& name, const SplineSurfaceData& n) {
  std::ostringstream net;
  net << '(';
  for (std::size_t i = 0; i < n.points.size(); ++i) {
    std::vector<int> row;
    for (const Vec3& p : n.points[i]) row.push_back(d->add("CARTESIAN_POINT('',", vec3(p), ")"));
    net << (i ? "," : "") << list(row, ref);
  }
  net << ')';
  std::vector<double> ku, kv;
  std::vector<int> mu, mv;
  distinct_knots(n.knots_u, &ku, &mu);
  distinct_knots(n.knots_v, &kv, &mv);
  std::ostringstream knots;
  knots << list(mu, count) << ',' << list(mv, count) << ',' << list(ku, step_real) << ',' << list(kv, step_real)
        << ",.UNSPECIFIED.";
  std::ostringstream o;
  if (n.weights.empty()) {
    o << "B_SPLINE_SURFACE_WITH_KNOTS(" << step_string(name) << ',' << n.degree_u << ',' << n.degree_v << ','
      << net.str() << ",.UNSPECIFIED.,.F.,.F.,.U.," << knots.str() << ')';
    return d->add(o.str());
  }
  std::ostringstream w;
  w << '(';
  for (std::size_t i = 0; i < n.weights.size(); ++i) w << (i ? "," : "") << list(n.weights[i], step_real);
  w << ')';
  o << "(BOUNDED_SURFACE()B_SPLINE_SURFACE(" << n.degree_u << ',' << n.degree_v << ',' << net.str()
    << ",.UNSPECIFIED.,.F.,.F.,.U.)B_SPLINE_SURFACE_WITH_KNOTS(" << knots.str()
    << ")GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE(" << w.str() << ")REPRESENTATION_ITEM("
    << step_string(name) << ")SURFACE())";
  return d->add(o.str());
}

// The surface in ISO 10303-42 form with ssimarch's parameterisation (docs/cad.md), or 0 for a
// kind STEP has no entity for (expression surfaces, ellipsoids, paraboloids, capsules) and for
// spline surfaces whose control data the caller does not have (`spline`: null).
int add_surface(StepData* d, const std::string& name, const Surface& surface, const SplineSurfaceData* spline) {
  const std::string n = step_string(name);
  if (surface.get_if<BSplineSurface>() || surface.get_if<BezierPatch>())
    return spline ? add_spline_surface(d, name, *spline) : 0;
  if (const auto* p = surface.get_if<Plane>())
    return add_trimmed(d, name, d->add("PLANE(", n, ",", ref(add_placement(d, p->frame())), ")"), p->domain());
  if (const auto* c = surface.get_if<Cylinder>())
    return add_trimmed(
        d, name,
        d->add("CYLINDRICAL_SURFACE(", n, ",", ref(add_placement(d, c->frame())), ",", step_real(c->radius()), ")"),
        c->domain());
  if (const auto* c = surface.get_if<Cone>())  // placed at the apex with radius 0: v is ssimarch's
    return add_trimmed(
        d, name,
        d->add("CONICAL_SURFACE(", n, ",", ref(add_placement(d, c->frame())), ",0.,", step_real(c->half_angle()), ")"),
        c->domain());
  if (const auto* s = surface.get_if<Sphere>())
    return d->add("SPHERICAL_SURFACE(", n, ",", ref(add_placement(d, s->frame())), ",", step_real(s->radius()), ")");
  if (const auto* t = surface.get_if<Torus>())
    return d->add("TOROIDAL_SURFACE(", n, ",", ref(add_placement(d, t->frame())), ",", step_real(t->major_radius()),
                  ",", step_real(t->minor_radius()), ")");
  return 0;
}

// Curve c of a run with its p-curves: a SURFACE_CURVE (one surface written) or an
// INTERSECTION_CURVE (both) whose associated geometry is the PCURVE on each parametric surface
// and the surface itself for an implicit one (ISO 10303-42 §4.4.66-4.4.71); the bare
// B-spline when neither surface has a STEP form.
int add_curve(StepData* d, const IntersectionRun& r, std::size_t c, int ctx2, std::map<std::string, int>* surface_ids,
              const std::map<std::string, SplineSurfaceData>& splines) {
  const auto names = parametric_surface_names(r);
  const std::array<const Surface*, 2> surfaces{&r.problem.first(), &r.problem.second()};
  std::array<int, 2> surface_id{};
  for (std::size_t k = 0; k < 2; ++k) {
    auto [it, fresh] = surface_ids->emplace(names[k], 0);
    const auto spline = splines.find(names[k]);
    if (fresh) it->second = add_surface(d, names[k], *surfaces[k], spline == splines.end() ? nullptr : &spline->second);
    surface_id[k] = it->second;
  }
  std::ostringstream named;
  named << r.spec.name << " curve " << c;
  const std::string name = named.str();
  const CurveSpline& spline = *r.splines[c];
  const int curve = add_bspline(d, name, spline.curve);
  std::array<int, 2> assoc{surface_id[0], surface_id[1]};  // implicit sides: the surface
  for (std::size_t k = 0; k < spline.pcurves.size(); ++k) {
    std::ostringstream pnamed;
    pnamed << name << " pcurve on " << names[k];
    const std::string pname = pnamed.str();
    const int pc = add_bspline(d, pname, spline.pcurves[k]);
    const int rep = d->add("DEFINITIONAL_REPRESENTATION(", step_string(pname), ",(", ref(pc), "),", ref(ctx2), ")");
    if (surface_id[k]) assoc[k] = d->add("PCURVE(", step_string(pname), ",", ref(surface_id[k]), ",", ref(rep), ")");
  }
  std::vector<int> given;
  for (int a : assoc)
    if (a) given.push_back(a);
  if (given.empty()) return curve;
  return d->add(given.size() == 2 ? "INTERSECTION_CURVE(" : "SURFACE_CURVE(", step_string(name), ",", ref(curve), ",",
                list(given, ref), ",.CURVE_3D.)");
}

}  // namespace

void write_step(std::ostream& out, const std::vector<IntersectionRun>& runs, const Scene* scene) {
  static const std::map<std::string, SplineSurfaceData> kNone;
  const auto& splines = scene ? scene->spline_data : kNone;
  double largest = 0;
  bool any = false;
  for (const IntersectionRun& r : runs)
    for (const auto& s : r.splines)
      if (s) {
        any = true;
        largest = std::max(largest, s->max_deviation);
      }
  if (!any) throw InputError("STEP output", "no B-spline to write (trace with the option bspline = true)");
  StepData d;
  const auto [ctx3, ctx2, shape] = add_frame(&d, largest > 0 ? largest : 1e-12);
  std::vector<int> curves;
  std::map<std::string, int> surface_ids;  // scene surface name -> STEP id (0: no STEP form)
  for (const IntersectionRun& r : runs)
    for (std::size_t c = 0; c < r.splines.size(); ++c)
      if (r.splines[c]) curves.push_back(add_curve(&d, r, c, ctx2, &surface_ids, splines));
  const int set = d.add("GEOMETRIC_CURVE_SET('intersection curves',", list(curves, ref), ")");
  const int rep =
      d.add("GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('ssimarch',(", ref(set), "),", ref(ctx3), ")");
  d.add("SHAPE_DEFINITION_REPRESENTATION(", ref(shape), ",", ref(rep), ")");
  out << "ISO-10303-21;\nHEADER;\n"
      << "FILE_DESCRIPTION(('ssimarch intersection curves: certified B-splines and p-curves'),'2;1');\n"
      << "FILE_NAME('ssimarch curves','',(''),(''),'ssimarch','ssimarch','');\n"
      << "FILE_SCHEMA(('AP242_MANAGED_MODEL_BASED_3D_ENGINEERING_MIM_LF { 1 0 10303 442 1 1 4 }'));\n"
      << "ENDSEC;\nDATA;\n"
      << d.text() << "ENDSEC;\nEND-ISO-10303-21;\n";
}

}  // namespace ssimarch
