// Scene-file surfaces (docs/scene-format.md, "Surfaces"). Every check names the JSON path.
#include "ssimarch/surface/surface_json.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>

#include "ssimarch/core/error.hpp"

namespace ssimarch {
namespace {

using nlohmann::json;
using expr::Constants;

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string fmt_num(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

std::string index_path(const std::string& where, std::size_t i) { return where + "[" + std::to_string(i) + "]"; }

std::string kind_of(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "an unsupported JSON value";
  }
}

// An object with the given required and optional keys, nothing else.
class Fields {
 public:
  Fields(const json& obj, std::string where, std::initializer_list<const char*> required,
         std::initializer_list<const char*> optional)
      : obj_(obj), where_(std::move(where)) {
    if (!obj.is_object()) throw InputError(where_, "expected an object, got " + kind_of(obj));
    std::vector<std::string> known;
    for (const char* k : required) known.emplace_back(k);
    for (const char* k : optional) known.emplace_back(k);
    for (const char* k : required)
      if (!obj.contains(k)) throw InputError(where_, std::string("missing key '") + k + "' (keys: " + join(known) + ")");
    for (const auto& [k, v] : obj.items())
      if (std::find(known.begin(), known.end(), k) == known.end())
        throw InputError(where_ + "." + k, "unknown key '" + k + "' (keys: " + join(known) + ")");
  }
  bool has(const char* k) const { return obj_.contains(k); }
  const json& at(const char* k) const { return obj_.at(k); }
  std::string path(const char* k) const { return where_ + "." + k; }
  const std::string& where() const { return where_; }

 private:
  const json& obj_;
  std::string where_;
};

double number(const json& j, const Constants& c, const std::string& where) {
  double x;
  if (j.is_number()) {
    x = j.get<double>();
  } else if (j.is_string()) {
    x = expr::evaluate_constant(j.get<std::string>(), c, where);
  } else {
    throw InputError(where, "expected a number or an expression string, got " + kind_of(j));
  }
  if (!std::isfinite(x)) throw InputError(where, "the value is not a finite number");
  return x;
}

double positive(const json& j, const Constants& c, const std::string& where) {
  const double x = number(j, c, where);
  if (!(x > 0)) throw InputError(where, "must be > 0, got " + fmt_num(x));
  return x;
}

int integer(const json& j, const Constants& c, const std::string& where, int min) {
  const double x = number(j, c, where);
  if (x != std::floor(x) || x < min || x > 64)
    throw InputError(where, "must be an integer in [" + std::to_string(min) + ", 64], got " + fmt_num(x));
  return static_cast<int>(x);
}

const json& array_of(const json& j, std::size_t n, const std::string& where, const char* what) {
  if (!j.is_array()) throw InputError(where, std::string("expected ") + what + ", got " + kind_of(j));
  if (j.size() != n)
    throw InputError(where, std::string("expected ") + what + ", got " + std::to_string(j.size()) + " components");
  return j;
}

Vec3 vec3(const json& j, const Constants& c, const std::string& where) {
  array_of(j, 3, where, "3 components [x, y, z]");
  return {number(j[0], c, index_path(where, 0)), number(j[1], c, index_path(where, 1)),
          number(j[2], c, index_path(where, 2))};
}

Vec3 direction(const json& j, const Constants& c, const std::string& where) {
  const Vec3 v = vec3(j, c, where);
  if (!(v.norm() > 0)) throw InputError(where, "must be a non-zero vector");
  return v;
}

Interval interval(const json& j, const Constants& c, const std::string& where) {
  array_of(j, 2, where, "an interval [lo, hi]");
  const Interval i{number(j[0], c, index_path(where, 0)), number(j[1], c, index_path(where, 1))};
  if (!(i.lo < i.hi))
    throw InputError(where, "interval must have lo < hi, got [" + fmt_num(i.lo) + ", " + fmt_num(i.hi) + "]");
  return i;
}

Box box(const json& j, const Constants& c, const std::string& where) {
  array_of(j, 3, where, "a box [[xlo, xhi], [ylo, yhi], [zlo, zhi]]");
  return {interval(j[0], c, index_path(where, 0)), interval(j[1], c, index_path(where, 1)),
          interval(j[2], c, index_path(where, 2))};
}

// Optional direction of u = 0; must not be parallel to the axis (Frame::from_axis).
std::optional<Vec3> reference(const Fields& f, const Constants& c, const Vec3& axis) {
  constexpr double kMinReferenceSine = 1e-9;
  if (!f.has("reference")) return std::nullopt;
  const Vec3 r = direction(f.at("reference"), c, f.path("reference"));
  if (!(r.cross(axis).norm() > kMinReferenceSine * r.norm() * axis.norm()))
    throw InputError(f.path("reference"), "must not be parallel to the axis");
  return r;
}

Interval interval_or(const Fields& f, const char* key, const Constants& c, Interval fallback) {
  return f.has(key) ? interval(f.at(key), c, f.path(key)) : fallback;
}

// Constructor checks that the JSON layer cannot see (e.g. a reference parallel to the axis)
// come back with the surface's path.
template <class Make>
Surface build(const std::string& where, Make make) {
  try {
    return Surface(make());
  } catch (const InputError& e) {
    if (e.where().rfind(where, 0) == 0) throw;
    throw InputError(where, e.message());
  }
}

Surface plane(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"point", "normal"}, {"u", "v", "reference"});
  const Vec3 p = vec3(f.at("point"), c, f.path("point"));
  const Vec3 n = direction(f.at("normal"), c, f.path("normal"));
  ParamDomain d{interval_or(f, "u", c, {-1, 1}), interval_or(f, "v", c, {-1, 1})};
  const auto ref = reference(f, c, n);
  return build(where, [&] { return Plane(p, n, d, ref); });
}

Surface sphere(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "radius"}, {"axis", "reference"});
  const Vec3 ctr = vec3(f.at("center"), c, f.path("center"));
  const double r = positive(f.at("radius"), c, f.path("radius"));
  const Vec3 axis = f.has("axis") ? direction(f.at("axis"), c, f.path("axis")) : Vec3::UnitZ();
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Sphere(ctr, r, axis, ref); });
}

Surface cylinder(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"point", "axis", "radius"}, {"range", "reference"});
  const Vec3 p = vec3(f.at("point"), c, f.path("point"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double r = positive(f.at("radius"), c, f.path("radius"));
  const Interval range = interval_or(f, "range", c, {-1, 1});
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Cylinder(p, axis, r, range, ref); });
}

Surface cone(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"apex", "axis", "half_angle"}, {"range", "reference"});
  const Vec3 apex = vec3(f.at("apex"), c, f.path("apex"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double a = number(f.at("half_angle"), c, f.path("half_angle"));
  if (!(a > 0) || !(a < std::acos(-1.0) / 2))
    throw InputError(f.path("half_angle"), "must be in (0, pi/2) radians, got " + fmt_num(a));
  const Interval range = interval_or(f, "range", c, {0, 1});
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Cone(apex, axis, a, range, ref); });
}

Surface torus(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "axis", "major_radius", "minor_radius"}, {"reference"});
  const Vec3 ctr = vec3(f.at("center"), c, f.path("center"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double R = positive(f.at("major_radius"), c, f.path("major_radius"));
  const double r = positive(f.at("minor_radius"), c, f.path("minor_radius"));
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Torus(ctr, axis, R, r, ref); });
}

Surface ellipsoid(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "radii"}, {"axis", "reference"});
  const Vec3 ctr = vec3(f.at("center"), c, f.path("center"));
  const std::string rp = f.path("radii");
  array_of(f.at("radii"), 3, rp, "3 radii [r0, r1, r2]");
  const std::array<double, 3> radii{positive(f.at("radii")[0], c, index_path(rp, 0)),
                                    positive(f.at("radii")[1], c, index_path(rp, 1)),
                                    positive(f.at("radii")[2], c, index_path(rp, 2))};
  const Vec3 axis = f.has("axis") ? direction(f.at("axis"), c, f.path("axis")) : Vec3::UnitZ();
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Ellipsoid(ctr, radii, axis, ref); });
}

Surface paraboloid(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"vertex", "axis", "focal_length"}, {"u", "v", "reference"});
  const Vec3 vtx = vec3(f.at("vertex"), c, f.path("vertex"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const json& fl = f.at("focal_length");
  const std::string fp = f.path("focal_length");
  double fu, fv;
  if (fl.is_array()) {
    array_of(fl, 2, fp, "one focal length or two [f_u, f_v]");
    fu = positive(fl[0], c, index_path(fp, 0));
    fv = positive(fl[1], c, index_path(fp, 1));
  } else {
    fu = fv = positive(fl, c, fp);
  }
  ParamDomain d{interval_or(f, "u", c, {-1, 1}), interval_or(f, "v", c, {-1, 1})};
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Paraboloid(vtx, axis, fu, fv, d, ref); });
}

Surface capsule(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "axis", "radius", "length"}, {"reference"});
  const Vec3 ctr = vec3(f.at("center"), c, f.path("center"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double r = positive(f.at("radius"), c, f.path("radius"));
  const double len = number(f.at("length"), c, f.path("length"));
  if (len < 0) throw InputError(f.path("length"), "must be >= 0, got " + fmt_num(len));
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Capsule(ctr, axis, r, len, ref); });
}

std::string expression_source(const json& j, const std::string& where) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number()) return j.dump();
  throw InputError(where, "expected an expression string or a number, got " + kind_of(j));
}

Surface parametric(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"parametric", "u", "v"}, {"periodic"});
  const std::string xp = f.path("parametric");
  array_of(f.at("parametric"), 3, xp, "3 coordinate expressions [x(u,v), y(u,v), z(u,v)]");
  std::array<std::string, 3> src;
  for (std::size_t i = 0; i < 3; ++i) src[i] = expression_source(f.at("parametric")[i], index_path(xp, i));
  ParamDomain d{interval(f.at("u"), c, f.path("u")), interval(f.at("v"), c, f.path("v"))};
  if (f.has("periodic")) {
    const json& p = f.at("periodic");
    const std::string pp = f.path("periodic");
    if (!p.is_array()) throw InputError(pp, "expected an array of parameter names such as [\"u\"], got " + kind_of(p));
    for (std::size_t i = 0; i < p.size(); ++i) {
      const json& e = p[i];
      if (e == "u") d.periodic_u = true;
      else if (e == "v") d.periodic_v = true;
      else throw InputError(index_path(pp, i), "expected \"u\" or \"v\", got " + e.dump());
    }
  }
  return ExprParametric::compile(src, d, c, xp);
}

Surface implicit(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"implicit", "box"}, {});
  const std::string src = expression_source(f.at("implicit"), f.path("implicit"));
  const Box b = box(f.at("box"), c, f.path("box"));
  return ExprImplicit::compile(src, b, c, f.path("implicit"));
}

ControlNet control_net(const json& j, const Constants& c, const std::string& where) {
  if (!j.is_array() || j.empty())
    throw InputError(where, "expected a non-empty array of rows of points [[[x,y,z], ...], ...], got " + kind_of(j));
  ControlNet net;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string rp = index_path(where, i);
    if (!j[i].is_array()) throw InputError(rp, "expected a row of points [[x,y,z], ...], got " + kind_of(j[i]));
    net.emplace_back();
    for (std::size_t k = 0; k < j[i].size(); ++k) net.back().push_back(vec3(j[i][k], c, index_path(rp, k)));
  }
  return net;
}

WeightNet weight_net(const json& j, const Constants& c, const std::string& where) {
  if (!j.is_array()) throw InputError(where, "expected an array of rows of weights, got " + kind_of(j));
  WeightNet w;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string rp = index_path(where, i);
    if (!j[i].is_array()) throw InputError(rp, "expected a row of weights, got " + kind_of(j[i]));
    w.emplace_back();
    for (std::size_t k = 0; k < j[i].size(); ++k) w.back().push_back(positive(j[i][k], c, index_path(rp, k)));
  }
  return w;
}

std::vector<double> knots(const json& j, const Constants& c, const std::string& where) {
  if (!j.is_array()) throw InputError(where, "expected an array of knots, got " + kind_of(j));
  std::vector<double> k;
  for (std::size_t i = 0; i < j.size(); ++i) k.push_back(number(j[i], c, index_path(where, i)));
  return k;
}

Surface bezier(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"control_points"}, {"weights"});
  const ControlNet net = control_net(f.at("control_points"), c, f.path("control_points"));
  const WeightNet w = f.has("weights") ? weight_net(f.at("weights"), c, f.path("weights")) : WeightNet{};
  return BezierPatch(net, w, where);
}

Surface bspline(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"degree", "knots_u", "knots_v", "control_points"}, {"weights"});
  const json& dj = f.at("degree");
  const std::string dp = f.path("degree");
  int p, q;
  if (dj.is_array()) {
    array_of(dj, 2, dp, "one degree or two [p, q]");
    p = integer(dj[0], c, index_path(dp, 0), 1);
    q = integer(dj[1], c, index_path(dp, 1), 1);
  } else {
    p = q = integer(dj, c, dp, 1);
  }
  const ControlNet net = control_net(f.at("control_points"), c, f.path("control_points"));
  const WeightNet w = f.has("weights") ? weight_net(f.at("weights"), c, f.path("weights")) : WeightNet{};
  return BSplineSurface(p, q, knots(f.at("knots_u"), c, f.path("knots_u")), knots(f.at("knots_v"), c, f.path("knots_v")),
                        net, w, where);
}

using Maker = Surface (*)(const json&, const Constants&, const std::string&);
struct Kind {
  const char* key;
  Maker make;
  bool flat;  // keys beside the type key (parametric, implicit) rather than nested in it
};
const Kind kKinds[] = {
    {"plane", plane, false},           {"sphere", sphere, false},         {"cylinder", cylinder, false},
    {"cone", cone, false},             {"torus", torus, false},           {"ellipsoid", ellipsoid, false},
    {"paraboloid", paraboloid, false}, {"capsule", capsule, false},       {"spherocylinder", capsule, false},
    {"parametric", parametric, true},  {"implicit", implicit, true},      {"bezier", bezier, false},
    {"bspline", bspline, false},       {"nurbs", bspline, false},
};

}  // namespace

const std::vector<std::string>& surface_type_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& k : kKinds) v.emplace_back(k.key);
    return v;
  }();
  return names;
}

Surface surface_from_json(const json& spec, const Constants& constants, const std::string& where) {
  if (!spec.is_object())
    throw InputError(where, "a surface must be an object such as {\"sphere\": {...}}, got " + kind_of(spec));
  const Kind* found = nullptr;
  for (const auto& k : kKinds) {
    if (!spec.contains(k.key)) continue;
    if (found)
      throw InputError(where, std::string("a surface has exactly one type key, got both '") + found->key + "' and '" +
                                  k.key + "'");
    found = &k;
  }
  if (!found) {
    std::vector<std::string> keys;
    for (const auto& [k, v] : spec.items()) keys.push_back("'" + k + "'");
    throw InputError(where, "unknown surface type " + (keys.empty() ? std::string("(empty object)") : join(keys)) +
                                "; known types: " + join(surface_type_names()));
  }
  if (found->flat) return found->make(spec, constants, where);
  if (spec.size() != 1) {
    for (const auto& [k, v] : spec.items())
      if (k != found->key)
        throw InputError(where + "." + k, "unknown key '" + k + "' beside '" + found->key + "' (the " + found->key +
                                              "'s data goes inside \"" + found->key + "\": {...})");
  }
  return found->make(spec.at(found->key), constants, where + "." + found->key);
}

}  // namespace ssimarch
