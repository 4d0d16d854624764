// Scene-file surfaces (docs/scene-format.md, "Surfaces"). Every check names the JSON path; the
// shared readers and their messages are io/json_reader.hpp.
#include "ssimarch/io/surface_json.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/json_reader.hpp"

namespace ssimarch {
namespace {

using nlohmann::json;

using Fields = JsonObject;

double positive(const json& j, const Constants& c, const std::string& where) {
  const double x = json_number(j, c, where);
  if (!(x > 0)) throw InputError(where, "must be > 0, got " + format_number(x));
  return x;
}

int integer(const json& j, const Constants& c, const std::string& where, int min) {
  const double x = json_number(j, c, where);
  if (x != std::floor(x) || x < min || x > 64)
    throw InputError(where, "must be an integer in [" + std::to_string(min) + ", 64], got " + format_number(x));
  return static_cast<int>(x);
}

Vec3 direction(const json& j, const Constants& c, const std::string& where) {
  const Vec3 v = json_vec3(j, c, where);
  if (!(v.norm() > 0)) throw InputError(where, "must be a non-zero vector");
  return v;
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
  return f.has(key) ? json_interval(f.at(key), c, f.path(key)) : fallback;
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
  const Vec3 p = json_vec3(f.at("point"), c, f.path("point"));
  const Vec3 n = direction(f.at("normal"), c, f.path("normal"));
  ParamDomain d{interval_or(f, "u", c, {-1, 1}), interval_or(f, "v", c, {-1, 1})};
  // Without "u" / "v" the plane is unbounded that way (surface/unbounded.hpp; issue 29).
  d.unbounded_u = !f.has("u");
  d.unbounded_v = !f.has("v");
  const auto ref = reference(f, c, n);
  return build(where, [&] { return Plane(p, n, d, ref); });
}

Surface sphere(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "radius"}, {"axis", "reference"});
  const Vec3 ctr = json_vec3(f.at("center"), c, f.path("center"));
  const double r = positive(f.at("radius"), c, f.path("radius"));
  const Vec3 axis = f.has("axis") ? direction(f.at("axis"), c, f.path("axis")) : Vec3::UnitZ();
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Sphere(ctr, r, axis, ref); });
}

Surface cylinder(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"point", "axis", "radius"}, {"range", "reference"});
  const Vec3 p = json_vec3(f.at("point"), c, f.path("point"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double r = positive(f.at("radius"), c, f.path("radius"));
  const Interval range = interval_or(f, "range", c, {-1, 1});
  const auto ref = reference(f, c, axis);
  return build(where, [&] {
    Cylinder s(p, axis, r, range, ref);
    s.mark_unbounded(false, !f.has("range"));  // infinite along its axis without "range"
    return s;
  });
}

Surface cone(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"apex", "axis", "half_angle"}, {"range", "reference"});
  const Vec3 apex = json_vec3(f.at("apex"), c, f.path("apex"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double a = json_number(f.at("half_angle"), c, f.path("half_angle"));
  if (!(a > 0) || !(a < std::acos(-1.0) / 2))
    throw InputError(f.path("half_angle"), "must be in (0, pi/2) radians, got " + format_number(a));
  const Interval range = interval_or(f, "range", c, {0, 1});
  const auto ref = reference(f, c, axis);
  return build(where, [&] {
    Cone s(apex, axis, a, range, ref);
    s.mark_unbounded(false, !f.has("range"));  // both nappes, infinite, without "range"
    return s;
  });
}

Surface torus(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "axis", "major_radius", "minor_radius"}, {"reference"});
  const Vec3 ctr = json_vec3(f.at("center"), c, f.path("center"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double R = positive(f.at("major_radius"), c, f.path("major_radius"));
  const double r = positive(f.at("minor_radius"), c, f.path("minor_radius"));
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Torus(ctr, axis, R, r, ref); });
}

Surface ellipsoid(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "radii"}, {"axis", "reference"});
  const Vec3 ctr = json_vec3(f.at("center"), c, f.path("center"));
  const std::string rp = f.path("radii");
  json_array(f.at("radii"), 3, rp, "3 radii [r0, r1, r2]");
  const std::array<double, 3> radii{positive(f.at("radii")[0], c, index_path(rp, 0)),
                                    positive(f.at("radii")[1], c, index_path(rp, 1)),
                                    positive(f.at("radii")[2], c, index_path(rp, 2))};
  const Vec3 axis = f.has("axis") ? direction(f.at("axis"), c, f.path("axis")) : Vec3::UnitZ();
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Ellipsoid(ctr, radii, axis, ref); });
}

Surface paraboloid(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"vertex", "axis", "focal_length"}, {"u", "v", "reference"});
  const Vec3 vtx = json_vec3(f.at("vertex"), c, f.path("vertex"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const json& fl = f.at("focal_length");
  const std::string fp = f.path("focal_length");
  double fu, fv;
  if (fl.is_array()) {
    json_array(fl, 2, fp, "one focal length or two [f_u, f_v]");
    fu = positive(fl[0], c, index_path(fp, 0));
    fv = positive(fl[1], c, index_path(fp, 1));
  } else {
    fu = fv = positive(fl, c, fp);
  }
  ParamDomain d{interval_or(f, "u", c, {-1, 1}), interval_or(f, "v", c, {-1, 1})};
  d.unbounded_u = !f.has("u");
  d.unbounded_v = !f.has("v");
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Paraboloid(vtx, axis, fu, fv, d, ref); });
}

Surface capsule(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"center", "axis", "radius", "length"}, {"reference"});
  const Vec3 ctr = json_vec3(f.at("center"), c, f.path("center"));
  const Vec3 axis = direction(f.at("axis"), c, f.path("axis"));
  const double r = positive(f.at("radius"), c, f.path("radius"));
  const double len = json_number(f.at("length"), c, f.path("length"));
  if (len < 0) throw InputError(f.path("length"), "must be >= 0, got " + format_number(len));
  const auto ref = reference(f, c, axis);
  return build(where, [&] { return Capsule(ctr, axis, r, len, ref); });
}

std::string expression_source(const json& j, const std::string& where) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number()) return j.dump();
  throw InputError(where, "expected an expression string or a number, got " + json_kind(j));
}

Surface parametric(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"parametric", "u", "v"}, {"periodic"});
  const std::string xp = f.path("parametric");
  json_array(f.at("parametric"), 3, xp, "3 coordinate expressions [x(u,v), y(u,v), z(u,v)]");
  std::array<std::string, 3> src;
  for (std::size_t i = 0; i < 3; ++i) src[i] = expression_source(f.at("parametric")[i], index_path(xp, i));
  ParamDomain d{json_interval(f.at("u"), c, f.path("u")), json_interval(f.at("v"), c, f.path("v"))};
  if (f.has("periodic")) {
    const json& p = f.at("periodic");
    const std::string pp = f.path("periodic");
    if (!p.is_array()) throw InputError(pp, "expected an array of parameter names such as [\"u\"], got " + json_kind(p));
    for (std::size_t i = 0; i < p.size(); ++i) {
      const json& e = p[i];
      if (e != "u" && e != "v") throw InputError(index_path(pp, i), "expected \"u\" or \"v\", got " + e.dump());
      bool& flag = e == "u" ? d.periodic_u : d.periodic_v;
      if (flag) throw InputError(index_path(pp, i), e.dump() + " is named twice");
      flag = true;
    }
  }
  return ExprParametric::compile(src, d, c, xp);
}

Surface implicit(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"implicit", "box"}, {});
  const std::string src = expression_source(f.at("implicit"), f.path("implicit"));
  const Box b = json_box(f.at("box"), c, f.path("box"));
  return ExprImplicit::compile(src, b, c, f.path("implicit"));
}

ControlNet control_net(const json& j, const Constants& c, const std::string& where) {
  if (!j.is_array() || j.empty())
    throw InputError(where, "expected a non-empty array of rows of points [[[x,y,z], ...], ...], got " + json_kind(j));
  ControlNet net;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string rp = index_path(where, i);
    if (!j[i].is_array()) throw InputError(rp, "expected a row of points [[x,y,z], ...], got " + json_kind(j[i]));
    net.emplace_back();
    for (std::size_t k = 0; k < j[i].size(); ++k) net.back().push_back(json_vec3(j[i][k], c, index_path(rp, k)));
  }
  return net;
}

WeightNet weight_net(const json& j, const Constants& c, const std::string& where) {
  if (!j.is_array()) throw InputError(where, "expected an array of rows of weights, got " + json_kind(j));
  WeightNet w;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string rp = index_path(where, i);
    if (!j[i].is_array()) throw InputError(rp, "expected a row of weights, got " + json_kind(j[i]));
    w.emplace_back();
    for (std::size_t k = 0; k < j[i].size(); ++k) w.back().push_back(positive(j[i][k], c, index_path(rp, k)));
  }
  return w;
}

std::vector<double> knots(const json& j, const Constants& c, const std::string& where) {
  if (!j.is_array()) throw InputError(where, "expected an array of knots, got " + json_kind(j));
  std::vector<double> k;
  for (std::size_t i = 0; i < j.size(); ++i) k.push_back(json_number(j[i], c, index_path(where, i)));
  return k;
}

SplineSurfaceData bezier_data(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"control_points"}, {"weights"});
  SplineSurfaceData d;
  d.points = control_net(f.at("control_points"), c, f.path("control_points"));
  d.weights = f.has("weights") ? weight_net(f.at("weights"), c, f.path("weights")) : WeightNet{};
  d.degree_u = static_cast<int>(d.points.size()) - 1;
  d.degree_v = d.points.empty() ? -1 : static_cast<int>(d.points[0].size()) - 1;
  for (auto [degree, k] : {std::pair{d.degree_u, &d.knots_u}, std::pair{d.degree_v, &d.knots_v}}) {
    k->assign(static_cast<std::size_t>(std::max(degree + 1, 0)), 0.0);
    k->resize(2 * k->size(), 1.0);
  }
  return d;
}

Surface bezier(const json& j, const Constants& c, const std::string& where) {
  const SplineSurfaceData d = bezier_data(j, c, where);
  return BezierPatch(d.points, d.weights, where);
}

SplineSurfaceData bspline_data(const json& j, const Constants& c, const std::string& where) {
  Fields f(j, where, {"degree", "knots_u", "knots_v", "control_points"}, {"weights"});
  const json& dj = f.at("degree");
  const std::string dp = f.path("degree");
  SplineSurfaceData d;
  if (dj.is_array()) {
    json_array(dj, 2, dp, "one degree or two [p, q]");
    d.degree_u = integer(dj[0], c, index_path(dp, 0), 1);
    d.degree_v = integer(dj[1], c, index_path(dp, 1), 1);
  } else {
    d.degree_u = d.degree_v = integer(dj, c, dp, 1);
  }
  d.points = control_net(f.at("control_points"), c, f.path("control_points"));
  d.weights = f.has("weights") ? weight_net(f.at("weights"), c, f.path("weights")) : WeightNet{};
  d.knots_u = knots(f.at("knots_u"), c, f.path("knots_u"));
  d.knots_v = knots(f.at("knots_v"), c, f.path("knots_v"));
  return d;
}

Surface bspline(const json& j, const Constants& c, const std::string& where) {
  const SplineSurfaceData d = bspline_data(j, c, where);
  return BSplineSurface(d.degree_u, d.degree_v, d.knots_u, d.knots_v, d.points, d.weights, where);
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
    throw InputError(where, "a surface must be an object such as {\"sphere\": {...}}, got " + json_kind(spec));
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
    throw InputError(where, "unknown surface type " + (keys.empty() ? std::string("(empty object)") : join_names(keys)) +
                                "; known types: " + join_names(surface_type_names()));
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

std::optional<SplineSurfaceData> spline_data_from_json(const json& spec, const Constants& constants, const std::string& where) {
  for (const char* key : {"bspline", "nurbs"})
    if (spec.is_object() && spec.contains(key)) return bspline_data(spec.at(key), constants, where + "." + key);
  if (spec.is_object() && spec.contains("bezier")) return bezier_data(spec.at("bezier"), constants, where + ".bezier");
  return std::nullopt;
}

}  // namespace ssimarch
