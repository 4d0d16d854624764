// Bezier extraction of B-spline surfaces by blossoming (include/ssimarch/surface/bezier_extraction.hpp).
#include "ssimarch/surface/bezier_extraction.hpp"

namespace ssimarch::internal {
namespace {

using H = std::array<double, 4>;

// Non-empty spans k of the domain (degree <= k < n) and, for every domain span, its piece.
void spans(std::span<const double> knots, int degree, int n, std::vector<int>* pieces_k, std::vector<int>* piece_of,
           std::vector<double>* breaks) {
  for (int k = degree; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (knots[i] < knots[i + 1]) {
      if (breaks->empty()) breaks->push_back(knots[i]);
      breaks->push_back(knots[i + 1]);
      pieces_k->push_back(k);
    }
    piece_of->push_back(std::max(0, static_cast<int>(pieces_k->size()) - 1));
  }
}

// The Bezier points of span k of the curve with control points at(0..n-1): b_i = f(a^(p-i) b^i),
// each one de Boor triangle whose level r takes a for r <= p - i and b after.
template <class At>
void span_bezier(At at, std::span<const double> knots, int p, int k, std::vector<H>& d, H* out) {
  const double a = knots[static_cast<std::size_t>(k)], b = knots[static_cast<std::size_t>(k + 1)];
  d.resize(static_cast<std::size_t>(p + 1));
  for (int i = 0; i <= p; ++i) {
    for (int j = 0; j <= p; ++j) d[static_cast<std::size_t>(j)] = at(k - p + j);
    for (int r = 1; r <= p; ++r) {
      const double t = r <= p - i ? a : b;
      for (int j = p; j >= r; --j) {
        // The denominator spans [knots[k], knots[k + 1]] at least, so it is positive.
        const double lo = knots[static_cast<std::size_t>(j + k - p)],
                     hi = knots[static_cast<std::size_t>(j + 1 + k - r)];
        const double alpha = (t - lo) / (hi - lo), beta = 1.0 - alpha;
        H& dj = d[static_cast<std::size_t>(j)];
        const H& dm = d[static_cast<std::size_t>(j - 1)];
        for (std::size_t c = 0; c < 4; ++c) dj[c] = beta * dm[c] + alpha * dj[c];
      }
    }
    out[i] = d[static_cast<std::size_t>(p)];
  }
}

}  // namespace

std::optional<BezierExtraction> extract_bezier_pieces(int p, int q, std::span<const double> knots_u,
                                                      std::span<const double> knots_v, int nu, int nv,
                                                      std::span<const H> homogeneous) {
  BezierExtraction e;
  e.p = p;
  e.q = q;
  std::vector<int> ku, kv;
  spans(knots_u, p, nu, &ku, &e.piece_of_span_u, &e.breaks_u);
  spans(knots_v, q, nv, &kv, &e.piece_of_span_v, &e.breaks_v);
  const std::size_t per_piece = static_cast<std::size_t>((p + 1) * (q + 1));
  const std::size_t rows_v = static_cast<std::size_t>(nu) * kv.size() * static_cast<std::size_t>(q + 1);
  const std::size_t points = ku.size() * kv.size() * per_piece + rows_v;
  if (points > kBezierExtractionBytes / sizeof(H)) return std::nullopt;
  // Along v first: row i's Bezier points of v-piece j at by_v[(i * pieces_v + j) * (q + 1) + l].
  std::vector<H> by_v(rows_v), d;
  for (int i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < kv.size(); ++j) {
      const auto at = [&](int c) { return homogeneous[static_cast<std::size_t>(i * nv + c)]; };
      span_bezier(at, knots_v, q, kv[j], d, by_v.data() + (static_cast<std::size_t>(i) * kv.size() + j) * (q + 1));
    }
  // Then along u, for each v-piece and each of its q + 1 columns.
  e.nets.resize(ku.size() * kv.size() * per_piece);
  std::vector<H> column(static_cast<std::size_t>(p + 1));
  for (std::size_t i = 0; i < ku.size(); ++i)
    for (std::size_t j = 0; j < kv.size(); ++j)
      for (int l = 0; l <= q; ++l) {
        const auto at = [&](int r) {
          return by_v[(static_cast<std::size_t>(r) * kv.size() + j) * static_cast<std::size_t>(q + 1) +
                      static_cast<std::size_t>(l)];
        };
        span_bezier(at, knots_u, p, ku[i], d, column.data());
        H* net = e.nets.data() + (i * kv.size() + j) * per_piece;
        for (int a = 0; a <= p; ++a)
          net[static_cast<std::size_t>(a * (q + 1) + l)] = column[static_cast<std::size_t>(a)];
      }
  return e;
}

}  // namespace ssimarch::internal
