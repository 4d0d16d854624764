#include "ssimarch/start/saddle_box.hpp"
#include "ssimarch/start/interval_forms.hpp"

#include <cmath>

#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/start/interval_hessian.hpp"

namespace ssimarch {

namespace {

IntervalNumber hessian_determinant(const IntervalNumber& a, const IntervalNumber& b, const IntervalNumber& c) {
  return a * c - b * b;  // [[a, b], [b, c]]
}

// Two unknowns: the curve is h(u, v) = 0 on the box itself.
bool saddle_2(const Problem& P, const IntervalBox& box) {
  IntervalSecond h[kMaxSystemDimension - 1];
  interval_second_derivatives(P, box, h);
  const auto& d = h[0].d;
  return hessian_determinant(d[0].d[0], d[0].d[1], d[1].d[1]).hi() < 0;
}

// The sign of g over the face x_a = at of the box: +1, -1, or 0 where it is not proven.
int face_sign(const Problem& P, const IntervalBox& box, int a, double at) {
  IntervalNumber x[kMaxSystemDimension], h[kMaxSystemDimension - 1];
  for (int i = 0; i < P.dim(); ++i) x[i] = i == a ? IntervalNumber(at) : box[static_cast<std::size_t>(i)];
  P.residual(x, h);
  return h[1].lo() > 0 ? 1 : (h[1].hi() < 0 ? -1 : 0);
}

// Three unknowns, f = g = 0. If g_a is proven non-zero on the box and g has opposite signs on the
// two faces x_a = lo, hi, the surface g = 0 in the box is the graph x_a = phi(x_b, x_c) over the
// whole rectangle of (x_b, x_c) (a disc); the curve is the zero set of f~ = f(phi) there, whose
// Hessian is t_i^T (Hess f - (f_a / g_a) Hess g) t_j with the tangents t_b = e_b - (g_b/g_a) e_a,
// t_c likewise (implicit differentiation of g(phi) = 0). Equal signs: g has no zero in the box.
bool saddle_3(const Problem& P, const IntervalBox& box) {
  IntervalSecond h[kMaxSystemDimension - 1];
  interval_second_derivatives(P, box, h);
  const auto& f = h[0].d;
  const auto& g = h[1].d;
  int a = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(g[static_cast<std::size_t>(i)].v.mid()) > std::abs(g[static_cast<std::size_t>(a)].v.mid())) a = i;
  const auto ua = static_cast<std::size_t>(a);
  if (g[ua].v.contains_zero()) return false;
  const int below = face_sign(P, box, a, box[ua].lo()), above = face_sign(P, box, a, box[ua].hi());
  if (below == 0 || above == 0) return false;
  if (below == above) return true;  // g is monotone along x_a and has one sign at both ends: no surface
  const IntervalNumber lambda = f[ua].v / g[ua].v;
  IntervalNumber t[2][3];
  for (int k = 0, b = 0; b < 3; ++b) {
    if (b == a) continue;
    for (int i = 0; i < 3; ++i) t[k][i] = IntervalNumber(i == b ? 1.0 : 0.0);
    t[k][a] = -(g[static_cast<std::size_t>(b)].v / g[ua].v);
    ++k;
  }
  IntervalNumber q[2][2];
  for (int k = 0; k < 2; ++k)
    for (int l = k; l < 2; ++l) {
      IntervalNumber s(0.0);
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) s = s + t[k][i] * (f[i].d[j] - lambda * g[i].d[j]) * t[l][j];
      q[k][l] = s;
    }
  return hessian_determinant(q[0][0], q[0][1], q[1][1]).hi() < 0;
}

}  // namespace

bool saddle_everywhere(const Problem& P, const IntervalBox& box) {
  if (P.dim() == 2) return saddle_2(P, box);
  if (P.dim() == 3) return saddle_3(P, box);
  return false;
}

SaddleBoxResult decide_saddle_box(const Problem& P, const IntervalBox& box, const RootSearchOptions& options) {
  SaddleBoxResult r;
  if (!saddle_everywhere(P, box)) return r;
  r.saddle = true;
  for (int i = 0; i < P.dim(); ++i)
    for (double at : {box[static_cast<std::size_t>(i)].lo(), box[static_cast<std::size_t>(i)].hi()}) {
      IntervalBox face;
      for (int j = 0; j < P.dim(); ++j)
        if (j != i) face.push_back(box[static_cast<std::size_t>(j)]);
      const RootSearchResult roots = find_all_roots(face_system(P, i, at), face, options);
      r.boxes += roots.boxes;
      if (!roots.complete()) return r;
      for (const CertifiedRoot& root : roots.roots) {
        VecX x(P.dim());
        for (int j = 0, k = 0; j < P.dim(); ++j) x[j] = j == i ? at : root.x[k++];
        r.crossings.push_back(std::move(x));
      }
    }
  r.decided = true;
  return r;
}

}  // namespace ssimarch
