#include "ssimarch/io/step_writer.hpp"

#include <charconv>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/trace_writers.hpp"

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
  d->add("APPLICATION_PROTOCOL_DEFINITION('international standard','ap242_managed_model_based_3d_engineering',2014,", ref(app), ")");
  const int pc = d->add("PRODUCT_CONTEXT('',", ref(app), ",'mechanical')");
  const int product = d->add("PRODUCT('ssimarch','intersection curves','',", list(std::vector<int>{pc}, ref), ")");
  const int formation = d->add("PRODUCT_DEFINITION_FORMATION('','',", ref(product), ")");
  const int pdc = d->add("PRODUCT_DEFINITION_CONTEXT('part definition',", ref(app), ",'design')");
  const int pd = d->add("PRODUCT_DEFINITION('design','',", ref(formation), ",", ref(pdc), ")");
  const int shape = d->add("PRODUCT_DEFINITION_SHAPE('',", ref(pd), ",", ref(pd), ")");
  const int length = d->add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))");
  const int angle = d->add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))");
  const int solid = d->add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())");
  const int uncertainty = d->add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(", step_real(tolerance), "),", ref(length) +
                                 ",'distance_accuracy_value','largest max_deviation of the curves')");
  const int ctx3 = d->add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((", ref(uncertainty) +
                          "))GLOBAL_UNIT_ASSIGNED_CONTEXT((", ref(length), ",", ref(angle), ",", ref(solid) +
                          "))REPRESENTATION_CONTEXT('3D','model space'))");
  const int ctx2 = d->add("(GEOMETRIC_REPRESENTATION_CONTEXT(2)PARAMETRIC_REPRESENTATION_CONTEXT()REPRESENTATION_CONTEXT("
                          "'2D','parameter space'))");
  return {ctx3, ctx2, shape};
}

}  // namespace

void write_step(std::ostream& out, const std::vector<IntersectionRun>& runs) {
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
  for (const IntersectionRun& r : runs) {
    const auto surfaces = parametric_surface_names(r);
    for (std::size_t c = 0; c < r.splines.size(); ++c) {
      if (!r.splines[c]) continue;
      std::ostringstream named;
      named << r.spec.name << " curve " << c;
      const std::string name = named.str();
      curves.push_back(add_bspline(&d, name, r.splines[c]->curve));
      for (std::size_t k = 0; k < r.splines[c]->pcurves.size(); ++k) {
        std::ostringstream pnamed;
        pnamed << name << " pcurve on " << surfaces[k];
        const std::string pname = pnamed.str();
        const int pc = add_bspline(&d, pname, r.splines[c]->pcurves[k]);
        d.add("DEFINITIONAL_REPRESENTATION(", step_string(pname), ",(", ref(pc), "),", ref(ctx2), ")");
      }
    }
  }
  const int set = d.add("GEOMETRIC_CURVE_SET('intersection curves',", list(curves, ref), ")");
  const int rep = d.add("GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('ssimarch',(", ref(set), "),", ref(ctx3), ")");
  d.add("SHAPE_DEFINITION_REPRESENTATION(", ref(shape), ",", ref(rep), ")");
  out << "ISO-10303-21;\nHEADER;\n"
      << "FILE_DESCRIPTION(('ssimarch intersection curves: certified B-splines and p-curves'),'2;1');\n"
      << "FILE_NAME('ssimarch curves','',(''),(''),'ssimarch','ssimarch','');\n"
      << "FILE_SCHEMA(('AP242_MANAGED_MODEL_BASED_3D_ENGINEERING_MIM_LF { 1 0 10303 442 1 1 4 }'));\n"
      << "ENDSEC;\nDATA;\n"
      << d.text() << "ENDSEC;\nEND-ISO-10303-21;\n";
}

}  // namespace ssimarch
