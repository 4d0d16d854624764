// The Bezier pieces of a B-spline surface (issue 27 item 1): one tensor-product Bezier piece per
// pair of non-empty knot spans, computed once when the surface is made, rational kept rational
// (the homogeneous net is converted). A piece's control points are the blossom of the span's
// polynomial at the span's ends, b_ij = f(a_u^(p-i) b_u^i ; a_v^(q-j) b_v^j) (Ramshaw 1989;
// Farin, "Curves and Surfaces for CAGD", 5th ed., sec. 8.4 and 10.3), each value one de Boor
// triangle with the span's ends as parameters; any knot vector (clamped or not, repeated knots).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "ssimarch/surface/bezier_piece.hpp"

namespace ssimarch::internal {

/// Memory bound of the pieces of one surface, bytes: the pieces take (p + 1)(q + 1) points per
/// pair of spans, about (p + 1)(q + 1) times the net. A surface whose pieces would take more is
/// evaluated by de Boor on its net (as before issue 27): slower jets, the same values.
inline constexpr std::size_t kBezierExtractionBytes = std::size_t{64} << 20;

struct BezierExtraction {
  int p = 0, q = 0;
  /// Piece (i, j) covers [breaks_u[i], breaks_u[i + 1]] x [breaks_v[j], breaks_v[j + 1]].
  std::vector<double> breaks_u, breaks_v;
  /// For knot span k (degree <= k < number of control points): the index of its piece; an empty
  /// span (a knot at the domain's end repeated degree + 1 times) maps to the piece before it.
  std::vector<int> piece_of_span_u, piece_of_span_v;
  /// Homogeneous control points of piece (i, j), row-major, from ((i * pieces_v + j) * (p + 1) * (q + 1)).
  std::vector<std::array<double, 4>> nets;

  int pieces_u() const { return static_cast<int>(breaks_u.size()) - 1; }
  int pieces_v() const { return static_cast<int>(breaks_v.size()) - 1; }
  /// The piece of knot spans (ku, kv) as find_span returns them.
  BezierPieceView view(int ku, int kv) const {
    const int i = piece_of_span_u[static_cast<std::size_t>(ku - p)];
    const int j = piece_of_span_v[static_cast<std::size_t>(kv - q)];
    const std::size_t at = static_cast<std::size_t>((i * pieces_v() + j) * (p + 1) * (q + 1));
    return {nets.data() + at,
            p,
            q,
            breaks_u[static_cast<std::size_t>(i)],
            breaks_u[static_cast<std::size_t>(i) + 1],
            breaks_v[static_cast<std::size_t>(j)],
            breaks_v[static_cast<std::size_t>(j) + 1]};
  }
};

/// The pieces of the B-spline surface of degrees (p, q) with validated knots and the
/// homogeneous net (nu x nv, row-major, i along u); std::nullopt when they would take more than
/// kBezierExtractionBytes.
std::optional<BezierExtraction> extract_bezier_pieces(int p, int q, std::span<const double> knots_u,
                                                      std::span<const double> knots_v, int nu, int nv,
                                                      std::span<const std::array<double, 4>> homogeneous);

}  // namespace ssimarch::internal
