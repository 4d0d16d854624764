#include "ssimarch/io/step_intersect.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "ssimarch/surface/box_pairs.hpp"

namespace ssimarch {

namespace {

// Where a face sits in its model's topology: the solid it bounds (FaceRegion::solid, empty for
// none) and the ids of its edges and vertices, sorted.
struct FaceTopology {
  std::string solid;
  std::vector<std::int64_t> parts;
};

FaceTopology topology_of(const StepModel& model, const StepFace& f) {
  FaceTopology t;
  const auto region = model.face_region(f.entity, f.placement);
  if (!region) return t;
  t.solid = region->solid();
  for (int i = 0; i < region->boundary_curves(); ++i) t.parts.push_back(region->boundary_edge(i));
  for (const auto& [id, p] : region->boundary_vertices()) t.parts.push_back(id);
  std::sort(t.parts.begin(), t.parts.end());
  return t;
}

// Faces of one solid that share no edge and no vertex do not meet (pipeline/shared_boundary.hpp).
bool apart_in_one_solid(const FaceTopology& a, const FaceTopology& b) {
  if (a.solid.empty() || a.solid != b.solid) return false;
  std::vector<std::int64_t> common;
  std::set_intersection(a.parts.begin(), a.parts.end(), b.parts.begin(), b.parts.end(), std::back_inserter(common));
  return common.empty();
}

// The faces of one set that could be read, with their placed boxes and topology.
struct ReadFaces {
  std::vector<int> faces;
  std::vector<Box> boxes;
  std::vector<FaceTopology> topology;
};

ReadFaces read_boxes(const StepFaceSet& set, const char* which, std::vector<std::string>* not_read) {
  ReadFaces out;
  for (int i : set.faces) {
    const StepFace& f = set.model->face(i, which);
    try {
      const Box box = set.model->surface(f.entity, f.placement).box();
      out.topology.push_back(topology_of(*set.model, f));
      out.boxes.push_back(box);
      out.faces.push_back(i);
    } catch (const InputError& e) {
      not_read->push_back(std::string(which) + " face " + std::to_string(i) + " (#" + std::to_string(f.entity) + ", " +
                          f.surface_type + "): " + e.what());
    }
  }
  return out;
}

double diagonal(const std::vector<Box>& boxes) {
  double d = 0;
  for (const Box& b : boxes) d = std::max(d, std::hypot(b.x.width(), b.y.width(), b.z.width()));
  return d;
}

}  // namespace

IntersectScene step_intersect_scene(const StepFaceSet& a, const StepFaceSet& b, bool same_model, bool solid_topology) {
  IntersectScene out;
  const ReadFaces ra = read_boxes(a, "A", &out.not_read), rb = read_boxes(b, "B", &out.not_read);
  const double slack = kIntersectBoxSlack * std::max(diagonal(ra.boxes), diagonal(rb.boxes));
  nlohmann::json surfaces = nlohmann::json::object(), pairs = nlohmann::json::array();
  auto name = [&](int set, int face) {
    std::string n = same_model ? "face" : (set == 0 ? "a" : "b");
    n += std::to_string(face);  // appended, not a chain of +: g++ 12 warns (-Wrestrict) on the chain
    return n;
  };
  // One model: a face in both sets meets the other set's faces once, as the pair (min, max).
  std::set<std::pair<int, int>> seen;
  for (const auto& [i, j] : overlapping_boxes(ra.boxes, rb.boxes, slack)) {
    int p = ra.faces[static_cast<std::size_t>(i)], q = rb.faces[static_cast<std::size_t>(j)];
    if (same_model) {
      if (p == q) continue;
      if (p > q) std::swap(p, q);
      if (!seen.emplace(p, q).second) continue;
    }
    if (solid_topology &&
        apart_in_one_solid(ra.topology[static_cast<std::size_t>(i)], rb.topology[static_cast<std::size_t>(j)])) {
      ++out.culled_by_solid;
      continue;
    }
    const std::string sp = name(0, p), sq = name(same_model ? 0 : 1, q);
    surfaces[sp] = step_face_json(a.step, p, *a.model);
    surfaces[sq] = same_model ? step_face_json(a.step, q, *a.model) : step_face_json(b.step, q, *b.model);
    pairs.push_back({{"name", sp + "-" + sq}, {"surfaces", {sp, sq}}});
  }
  out.pairs = static_cast<int>(pairs.size());
  // Every pair the sets form, less the traced: in one model the ordered pairs of distinct faces,
  // each pair of faces in both sets counted once.
  const long na = static_cast<long>(ra.faces.size()), nb = static_cast<long>(rb.faces.size());
  long all = na * nb;
  if (same_model) {
    std::vector<int> sa = ra.faces, sb = rb.faces, both;
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    std::set_intersection(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(both));
    const long k = static_cast<long>(both.size());
    all -= k + k * (k - 1) / 2;
  }
  out.culled = static_cast<int>(all - out.pairs);
  out.scene = {{"surfaces", surfaces}, {"intersections", pairs}};
  return out;
}

}  // namespace ssimarch
