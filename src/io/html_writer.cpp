// Viewer pages (html_writer.hpp).
#include "ssimarch/io/html_writer.hpp"

#include <optional>

#include "ssimarch/core/contract.hpp"
#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/unbounded.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "ssimarch/core/error.hpp"
#include "ssimarch/porosity/correlation.hpp"

namespace ssimarch {

namespace {

// 10^places with 10^-places about 1e-5 of `size`: coordinates rounded to that many decimal places
// print short (the double nearest a short decimal prints as that decimal), so pages stay small; a
// display needs no more (WebGL holds floats).
double display_scale(double size) {
  return std::pow(10.0, std::clamp(static_cast<int>(std::ceil(-std::log10(1e-5 * std::max(size, 1e-300)))), 0, 15));
}

nlohmann::json mesh_json(const Surface& s, const TriangleMesh& m) {
  double size = 0;
  for (const Vec3& p : m.vertices) size = std::max(size, p.cwiseAbs().maxCoeff());
  const double scale = display_scale(size);
  std::vector<double> positions;
  positions.reserve(3 * m.vertices.size());
  for (const Vec3& p : m.vertices)
    for (int a = 0; a < 3; ++a) positions.push_back(std::round(p[a] * scale) / scale);
  std::vector<std::uint32_t> triangles;
  triangles.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  nlohmann::json js = {{"type", std::string(s.type_name())},
                       {"form", s.is_parametric() ? "parametric" : "implicit"},
                       {"positions", positions},
                       {"triangles", triangles}};
  if (s.is_parametric()) {
    const ParamDomain& d = s.domain();
    js["domain"] = {{"u", {d.u.lo, d.u.hi}}, {"v", {d.v.lo, d.v.hi}}};
  }
  return js;
}

nlohmann::json profile_json(const PorosityProfile& p) {
  nlohmann::json js = {{"x", p.x}, {"porosity", p.porosity}};
  if (!p.x_upper.empty()) js["x_upper"] = p.x_upper;
  return js;
}

nlohmann::json particles_json(std::span<const Particle> particles, bool spherocylinders) {
  double size = 0;
  for (const Particle& q : particles) size = std::max({size, q.centre.cwiseAbs().maxCoeff(), q.diameter + q.length});
  const double scale = display_scale(size), unit = display_scale(1.0);
  auto round = [](double x, double k) { return std::round(x * k) / k; };
  std::vector<double> centre, axis, diameter, length;
  for (const Particle& q : particles) {
    for (int a = 0; a < 3; ++a) centre.push_back(round(q.centre[a], scale));
    diameter.push_back(round(q.diameter, scale));
    if (!spherocylinders) continue;
    for (int a = 0; a < 3; ++a) axis.push_back(round(q.axis[a], unit));
    length.push_back(round(q.length, scale));
  }
  nlohmann::json js = {{"count", particles.size()}, {"centre", centre}, {"diameter", diameter}};
  if (spherocylinders) js["axis"] = axis, js["length"] = length;
  return js;
}

// de Klerk (2003) over the radial profile's radii (porosity/correlation.hpp), for spheres.
nlohmann::json correlation_json(const PorosityProfile& radial, double R, double d) {
  double core = 0;
  int n = 0;
  for (std::size_t j = 0; j < radial.x.size(); ++j)
    if (R - radial.x[j] > 2.5 * d) core += radial.porosity[j], ++n;
  if (n == 0) return nullptr;
  const double eps_b = core / n;
  std::vector<double> eps;
  for (double r : radial.x) eps.push_back(de_klerk_porosity((R - r) / d, eps_b));
  return {{"label", "de Klerk (2003), eps_b = mean exact porosity beyond 2.5 d"}, {"x", radial.x}, {"porosity", eps},
          {"eps_b", eps_b}, {"diameter", d}};
}

}  // namespace

nlohmann::json trace_page_data(const nlohmann::json& result, const Scene* scene, const std::string& title,
                               const SurfaceMeshOptions& mesh) {
  if (!result.is_object() || !result.contains("intersections") || !result["intersections"].is_array())
    throw InputError("viewer", "the result has no \"intersections\" array (expected the JSON of ssimarch trace)");
  nlohmann::json surfaces = nlohmann::json::object(), starts = nlohmann::json::object();
  if (scene) {
    std::set<std::string> names;
    for (const auto& in : result["intersections"]) {
      if (in.contains("surfaces") && in["surfaces"].is_array())
        for (const auto& s : in["surfaces"])
          if (s.is_string()) names.insert(s.get<std::string>());
      const IntersectionSpec* spec = in.contains("name") && in["name"].is_string() ? scene->intersection(in["name"].get<std::string>()) : nullptr;
      if (spec && !spec->starts.empty()) {
        nlohmann::json& list = starts[spec->name];
        for (const Vec3& p : spec->starts) list.push_back({p.x(), p.y(), p.z()});
      }
    }
    // An unbounded surface (surface/unbounded.hpp) is drawn over the bounded ones, as the trace
    // clips it; over its nominal rectangle the picture would hide where the curves are.
    std::optional<Box> bounded;
    for (const std::string& name : names) {
      const Surface& s = scene->surface(name);
      if (!has_unbounded_direction(s)) bounded = bounded ? box_union(*bounded, s.box()) : s.box();
    }
    for (const std::string& name : names) {
      const Surface& s = scene->surface(name);
      const Surface drawn = bounded ? clipped_to(s, *bounded) : s;
      surfaces[name] = mesh_json(drawn, surface_mesh(drawn, mesh));
    }
  }
  return {{"kind", "trace"},
          {"title", title},
          {"intersections", result["intersections"]},
          {"surfaces", surfaces},
          {"starts", starts}};
}

nlohmann::json porosity_page_data(const PorosityJobResult& r, std::span<const Particle> particles,
                                  const std::string& title) {
  const Container& c = r.container;
  nlohmann::json js = {{"kind", "porosity"},
                       {"title", title},
                       {"container", {{"radius", c.radius}, {"z_range", {c.slab.z_min, c.slab.z_max}}}},
                       {"spherocylinders", r.spherocylinders},
                       {"bulk_porosity", r.bulk.porosity},
                       {"particles", particles_json(particles, r.spherocylinders)}};
  if (r.radial) js["radial"] = profile_json(*r.radial);
  if (r.bins) js["bins"] = profile_json(*r.bins);
  if (r.axial) js["axial"] = profile_json(*r.axial);
  if (r.map) js["map"] = {{"r", r.map->r}, {"z", r.map->z}, {"porosity", r.map->porosity}};
  if (r.radial && !r.spherocylinders && !particles.empty()) {
    double d = 0;
    for (const Particle& q : particles) d += q.diameter;
    js["correlation"] = correlation_json(*r.radial, c.radius, d / static_cast<double>(particles.size()));
  }
  return js;
}

void write_viewer_page(std::ostream& out, const nlohmann::json& data, std::string_view script) {
  SSIMARCH_EXPECTS(!script.empty(), "write_viewer_page: no viewer script");
  SSIMARCH_EXPECTS(script.find("</script") == std::string_view::npos,
                   "write_viewer_page: the viewer script holds \"</script\" and cannot be inlined");
  const std::string dumped = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  // "<\/" is the same JSON string as "</" and cannot close the data's script element.
  std::string text;
  text.reserve(dumped.size());
  for (std::size_t i = 0; i < dumped.size(); ++i) {
    text += dumped[i];
    if (dumped[i] == '<' && i + 1 < dumped.size() && dumped[i + 1] == '/') text += '\\';
  }
  const std::string title = data.value("title", std::string("ssimarch"));
  std::string safe_title;
  for (char ch : title) safe_title += ch == '<' ? std::string("&lt;") : ch == '&' ? std::string("&amp;") : std::string(1, ch);
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<meta name=\"generator\" content=\"ssimarch (docs/viewer.md)\">\n"
      << "<title>" << safe_title << " - ssimarch viewer</title>\n</head><body>\n"
      << "<script type=\"application/json\" id=\"ssimarch-data\">" << text << "</script>\n"
      << "<script>" << script << "</script>\n</body></html>\n";
}

}  // namespace ssimarch
