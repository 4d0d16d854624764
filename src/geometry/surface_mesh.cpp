// Display meshes of surfaces (surface_mesh.hpp). Marching tetrahedra: Bloomenthal, "Polygonization
// of implicit surfaces", CAGD 5 (1988); the six-tetrahedra split of a cube around its diagonal
// (Kuhn triangulation) makes neighbouring cubes agree on their shared faces.
#include "ssimarch/geometry/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "ssimarch/core/error.hpp"

namespace ssimarch {

double TriangleMesh::area() const {
  double a = 0;
  for (const auto& t : triangles)
    a += 0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
  return a;
}

TriangleMesh mesh_parametric(const Surface& s, int grid_u, int grid_v) {
  if (grid_u < 1 || grid_v < 1) throw InputError("surface mesh", "the parametric grid needs at least one cell per direction");
  const ParamDomain& d = s.domain();
  TriangleMesh m;
  const int nu = grid_u + 1, nv = grid_v + 1;
  m.vertices.reserve(static_cast<std::size_t>(nu) * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = d.u.lo + d.u.width() * i / grid_u, v = d.v.lo + d.v.width() * j / grid_v;
      const Vec3T<double> p = s.point<double>(u, v);
      m.vertices.emplace_back(p.x, p.y, p.z);
    }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * nu + i); };
  auto finite = [&](std::uint32_t k) { return m.vertices[k].allFinite(); };
  for (int j = 0; j < grid_v; ++j)
    for (int i = 0; i < grid_u; ++i) {
      const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), e = id(i, j + 1);
      // (u, v) counter-clockwise: the normal of each triangle points along F_u x F_v.
      if (finite(a) && finite(b) && finite(c)) m.triangles.push_back({a, b, c});
      if (finite(a) && finite(c) && finite(e)) m.triangles.push_back({a, c, e});
    }
  return m;
}

namespace {

// A regular grid of f values over a box, with the edge vertices found so far (shared between the
// tetrahedra that meet at an edge, so the mesh is indexed).
class MarchingGrid {
 public:
  MarchingGrid(const Surface& s, const Box& box, int cells) : s_(s) {
    const double longest = std::max({box.x.width(), box.y.width(), box.z.width()});
    if (!(longest > 0) || !std::isfinite(longest)) throw InputError("surface mesh", "the box of an implicit surface is empty");
    const double h = longest / cells;
    const Interval* axes[3] = {&box.x, &box.y, &box.z};
    for (int a = 0; a < 3; ++a) {
      n_[a] = std::max(1, static_cast<int>(std::ceil(axes[a]->width() / h - 1e-9)));
      lo_[a] = axes[a]->lo;
      h_[a] = axes[a]->width() / n_[a];
    }
    f_.resize(static_cast<std::size_t>(n_[0] + 1) * (n_[1] + 1) * (n_[2] + 1));
    for (int k = 0; k <= n_[2]; ++k)
      for (int j = 0; j <= n_[1]; ++j)
        for (int i = 0; i <= n_[0]; ++i) f_[index(i, j, k)] = value(point(i, j, k));
  }

  TriangleMesh march() {
    // The six tetrahedra of a cube around its diagonal 0-7; corner bit 1 = +x, 2 = +y, 4 = +z.
    static constexpr int kTets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i) {
          std::size_t corner[8];
          for (int c = 0; c < 8; ++c) corner[c] = index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          for (const auto& t : kTets) tetrahedron({corner[t[0]], corner[t[1]], corner[t[2]], corner[t[3]]});
        }
    return std::move(mesh_);
  }

 private:
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * (n_[1] + 1) + j) * (n_[0] + 1) + i;
  }
  Vec3 point(int i, int j, int k) const { return {lo_[0] + h_[0] * i, lo_[1] + h_[1] * j, lo_[2] + h_[2] * k}; }
  Vec3 point(std::size_t g) const {
    const std::size_t nx = n_[0] + 1, ny = n_[1] + 1;
    return point(static_cast<int>(g % nx), static_cast<int>((g / nx) % ny), static_cast<int>(g / (nx * ny)));
  }
  double value(const Vec3& p) const { return s_.value<double>(Vec3T<double>{p.x(), p.y(), p.z()}); }
  bool inside(std::size_t g) const { return f_[g] < 0; }  // f = 0 counts as outside

  // The surface point on the grid edge (a inside, b outside): regula falsi, Illinois variant.
  std::uint32_t edge_vertex(std::size_t a, std::size_t b) {
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    if (auto it = edges_.find(key); it != edges_.end()) return it->second;
    const Vec3 pa = point(a), pb = point(b);
    double t0 = 0, t1 = 1, f0 = f_[a], f1 = f_[b];
    const double stop = 1e-12 * std::max(std::fabs(f0), std::fabs(f1));
    double t = f0 / (f0 - f1);
    for (int it = 0, side = 0; it < 60 && std::isfinite(t); ++it) {
      const double ft = value(pa + t * (pb - pa));
      if (!std::isfinite(ft) || std::fabs(ft) <= stop) break;
      if ((ft < 0) == (f0 < 0)) {
        t0 = t, f0 = ft;
        if (side == -1) f1 /= 2;
        side = -1;
      } else {
        t1 = t, f1 = ft;
        if (side == 1) f0 /= 2;
        side = 1;
      }
      t = t0 + (t1 - t0) * f0 / (f0 - f1);
    }
    if (!std::isfinite(t)) t = 0.5 * (t0 + t1);
    mesh_.vertices.push_back(pa + t * (pb - pa));
    const auto id = static_cast<std::uint32_t>(mesh_.vertices.size() - 1);
    edges_.emplace(key, id);
    return id;
  }

  // Adds a triangle wound so that its normal points from the inside corners to the outside ones.
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3& outward) {
    const Vec3& pa = mesh_.vertices[a];
    const Vec3 n = (mesh_.vertices[b] - pa).cross(mesh_.vertices[c] - pa);
    if (n.dot(outward) < 0) std::swap(b, c);
    mesh_.triangles.push_back({a, b, c});
  }

  void tetrahedron(const std::array<std::size_t, 4>& g) {
    std::size_t in[4], out[4];
    int ni = 0, no = 0;
    Vec3 ci = Vec3::Zero(), co = Vec3::Zero();
    for (std::size_t v : g) {
      if (inside(v)) in[ni++] = v, ci += point(v);
      else out[no++] = v, co += point(v);
    }
    if (ni == 0 || no == 0) return;
    const Vec3 outward = co / no - ci / ni;
    if (ni == 1 || no == 1) {  // one corner apart: one triangle
      const std::size_t lone = ni == 1 ? in[0] : out[0];
      const std::size_t* others = ni == 1 ? out : in;
      std::uint32_t v[3];
      for (int k = 0; k < 3; ++k) v[k] = ni == 1 ? edge_vertex(lone, others[k]) : edge_vertex(others[k], lone);
      triangle(v[0], v[1], v[2], outward);
      return;
    }
    // Two and two: a quadrilateral on the edges in0-out0, in0-out1, in1-out1, in1-out0.
    const std::uint32_t a = edge_vertex(in[0], out[0]), b = edge_vertex(in[0], out[1]), c = edge_vertex(in[1], out[1]),
                        d = edge_vertex(in[1], out[0]);
    triangle(a, b, c, outward);
    triangle(a, c, d, outward);
  }

  const Surface& s_;
  int n_[3] = {1, 1, 1};
  double lo_[3] = {0, 0, 0}, h_[3] = {1, 1, 1};
  std::vector<double> f_;
  std::unordered_map<std::uint64_t, std::uint32_t> edges_;
  TriangleMesh mesh_;
};

}  // namespace

TriangleMesh mesh_implicit(const Surface& s, const Box& box, int cells) {
  if (cells < 2) throw InputError("surface mesh", "marching needs at least 2 cells along the box");
  return MarchingGrid(s, box, cells).march();
}

TriangleMesh surface_mesh(const Surface& s, const SurfaceMeshOptions& options) {
  if (s.is_parametric()) return mesh_parametric(s, options.grid, options.grid);
  return mesh_implicit(s, s.box(), options.cells);
}

}  // namespace ssimarch
