#include "ssimarch/io/step_section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/step_surface_json.hpp"

namespace ssimarch {

SectionPlane parse_section_plane(const std::string& text, const std::string& where) {
  std::vector<double> x;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double v = std::numeric_limits<double>::quiet_NaN();
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < item.size() && std::isspace(static_cast<unsigned char>(item[used]))) ++used;
    if (item.empty() || used != item.size() || !std::isfinite(v))
      throw InputError(where,
                       "expected six finite numbers X,Y,Z,NX,NY,NZ (a point and the normal), got \"" + text + "\"");
    x.push_back(v);
  }
  if (x.size() != 6 || text.empty() || text.back() == ',')
    throw InputError(where, "expected six numbers X,Y,Z,NX,NY,NZ (a point and the normal), got \"" + text + "\"");
  const Vec3 n(x[3], x[4], x[5]);
  if (!(n.norm() > 0) || !std::isfinite(n.norm()))
    throw InputError(where, "the normal (NX,NY,NZ) must be a non-zero vector, got \"" + text + "\"");
  return {Vec3(x[0], x[1], x[2]), n.normalized()};
}

namespace {

// Whether the plane meets the box (its corners' signed distances do not all have one sign, with
// the slack of kSectionBoxSlack times the diagonal).
bool crosses(const SectionPlane& plane, const Box& b) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c((k & 1) ? b.x.hi : b.x.lo, (k & 2) ? b.y.hi : b.y.lo, (k & 4) ? b.z.hi : b.z.lo);
    const double d = plane.normal.dot(c - plane.point);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const double slack = kSectionBoxSlack * Vec3(b.x.width(), b.y.width(), b.z.width()).norm();
  return lo <= slack && hi >= -slack;
}

}  // namespace

SectionScene step_section_scene(const std::filesystem::path& step, const StepModel& model,
                                const std::vector<int>& faces, const std::vector<SectionPlane>& planes) {
  SectionScene out;
  nlohmann::json surfaces = nlohmann::json::object(), pairs = nlohmann::json::array();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const SectionPlane& p = planes[k];
    surfaces["plane" + std::to_string(k + 1)] = {
        {"plane",
         {{"point", {p.point.x(), p.point.y(), p.point.z()}}, {"normal", {p.normal.x(), p.normal.y(), p.normal.z()}}}}};
  }
  for (int i : faces) {
    const StepFace& f = model.face(i, "--faces");
    Box box;
    try {
      box = model.surface(f.entity, f.placement).box();
    } catch (const InputError& e) {
      out.not_read.push_back("face " + std::to_string(i) + " (#" + std::to_string(f.entity) + ", " + f.surface_type +
                             "): " + e.what());
      continue;
    }
    const std::string face = "face" + std::to_string(i);
    bool used = false;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      if (!crosses(planes[k], box)) {
        ++out.culled;
        continue;
      }
      const std::string plane = "plane" + std::to_string(k + 1);
      pairs.push_back({{"name", face + "-" + plane}, {"surfaces", {face, plane}}});
      used = true;
      ++out.pairs;
    }
    if (used) surfaces[face] = step_face_json(step, i, model);
  }
  out.scene = {{"surfaces", surfaces}, {"intersections", pairs}};
  return out;
}

}  // namespace ssimarch
