// Enclosures of Bezier pieces over a parameter box from their control nets (issue 27 item 2).
//
// The certified search (start/) evaluates the surfaces on interval boxes, in an interval type and
// in forward gradients over it, nested up to twice (start/gradient.hpp). De Casteljau or de Boor
// run in the interval type widen exponentially with the degree (each blend of two enclosures
// doubles the dependency), and de Boor chooses its knot span from the box's midpoint, which is
// wrong for a box across a knot line; that is why multi-span B-splines were not evaluated on
// intervals and every NURBS pair fell back to sampled start points, uncertified.
//
// Here a box is cut at the knot lines into the parts each piece covers (the part of a periodic
// direction beyond the seam taken on the other side), and on each part:
//
//   F^(a,b) = d^(a+b) H / du^a dv^b lies, over the part, in the convex hull of the Bernstein
//   coefficients of the piece's (a, b) hodograph restricted to the part
//
// (Farin, "Curves and Surfaces for CAGD", 5th ed., sec. 5.3 convex hull, 5.4 subdivision, 5.5
// hodograph; the coefficients of the restriction are the blossom at the part's ends, two de
// Casteljau subdivisions). H is the homogeneous polynomial (w x, w y, w z, w); rational pieces
// are divided in the number type (the quotient rule on enclosures), and the value of F is also
// bounded by the hull of the restricted net's projected points (weights > 0). Every step runs in
// the interval type, so rounding is enclosed. A number type T with depth k (an interval: 0, a
// gradient over a type of depth k - 1: k) is then assembled from the partials of order <= k by
// the chain rule, F(u).d_i = F_u(u) u.d_i + F_v(u) v.d_i (`compose`). Over a box met by several
// parts the enclosures are hulled, value and derivatives alike: sound for the mean-value and
// Krawczyk forms where F is C^(k - 1) across the knot lines in the box (the difference quotient of
// a continuous, piecewise smooth function lies in the hull of its one-sided derivatives). The
// B-spline checks C1 across its knot lines when it is made (c1_across_knot_lines) and is not
// evaluated on intervals otherwise (start/certified_start_points.hpp, evaluates_on_intervals).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/bezier_piece.hpp"

namespace ssimarch::internal {

/// An interval scalar (start/interval_number.hpp's IntervalNumber), named by what is used of it.
template <class T>
concept IntervalScalar = requires(const T& t) {
  { t.lo() } -> std::convertible_to<double>;
  { t.hi() } -> std::convertible_to<double>;
  T(0.0, 1.0);
};

/// Whether T encloses (an interval, or forward gradients over one), its depth (the order of
/// derivatives it carries) and its interval scalar.
template <class T>
struct Enclosure : std::false_type {};
template <IntervalScalar T>
struct Enclosure<T> : std::true_type {
  static constexpr int depth = 0;
  using Scalar = T;
};
template <class T>
requires requires(const T& t) {
  t.v;
  t.d.size();
} && Enclosure<std::remove_cvref_t<decltype(std::declval<T>().v)>>::value struct Enclosure<T> : std::true_type {
  using Inner = std::remove_cvref_t<decltype(std::declval<T>().v)>;
  static constexpr int depth = Enclosure<Inner>::depth + 1;
  using Scalar = typename Enclosure<Inner>::Scalar;
};

/// The interval of values of x (its derivatives' enclosures left out).
template <class T>
auto& innermost(T& x) {
  if constexpr (Enclosure<std::remove_const_t<T>>::depth == 0)
    return x;
  else
    return innermost(x.v);
}

/// The componentwise hull of two enclosures (values and every derivative).
template <class T>
T enclosure_hull(const T& x, const T& y) {
  if constexpr (Enclosure<T>::depth == 0) {
    return T(std::min<double>(x.lo(), y.lo()), std::max<double>(x.hi(), y.hi()));
  } else {
    T r = x;
    r.v = enclosure_hull(x.v, y.v);
    for (std::size_t i = 0; i < r.d.size(); ++i) r.d[i] = enclosure_hull(x.d[i], y.d[i]);
    return r;
  }
}

/// Partials up to this total order are enclosed (start/ nests gradients twice).
inline constexpr int kMaxEnclosureDepth = 3;
constexpr int partial_slot(int a, int b) { return (a + b) * (a + b + 1) / 2 + b; }
inline constexpr int kPartialSlots = partial_slot(0, kMaxEnclosureDepth) + 1;

/// Enclosures of the partials d^(a+b) H_c / du^a dv^b (a + b <= depth) of one piece over one part
/// of the box, and the hull of the restricted net's projected points (rational pieces).
template <class I, std::size_t D>
struct PartEnclosure {
  std::array<std::array<I, kPartialSlots>, D> partial;
  std::array<I, 3> projected;
  bool has_projected = false;
};

/// The Bernstein coefficients on [s0, s1] of the degree-n curve with coefficients b (in place),
/// s0 <= s1 in the curve's own parameter (outside [0, 1] too: the polynomial continued). Each
/// subdivision divides by a length >= 1/2: right part at s0 then left at (s1 - s0) / (1 - s0)
/// when s0 <= 1/2, else left at s1 then right at s0 / s1.
template <class I>
void restrict_curve(I* b, std::ptrdiff_t stride, int n, const I& s0, const I& s1) {
  const auto at = [b, stride](int i) -> I& { return b[static_cast<std::ptrdiff_t>(i) * stride]; };
  const auto keep_right = [&](const I& t) {
    const I s = I(1.0) - t;
    for (int r = 1; r <= n; ++r)
      for (int i = 0; i + r <= n; ++i) at(i) = s * at(i) + t * at(i + 1);
  };
  const auto keep_left = [&](const I& t) {
    const I s = I(1.0) - t;
    for (int r = 1; r <= n; ++r)
      for (int i = n; i >= r; --i) at(i) = s * at(i - 1) + t * at(i);
  };
  if (s0.hi() <= 0.5) {
    keep_right(s0);
    keep_left((s1 - s0) / (I(1.0) - s0));
  } else {
    keep_left(s1);
    keep_right(s0 / s1);
  }
}

template <class I>
std::vector<I>& enclosure_scratch() {
  thread_local std::vector<I> s;
  return s;
}

/// The hull of the piece's (a, b) hodograph of component c restricted to the part [u0, u1] x
/// [v0, v1] (global parameters, the piece's own parameter is (u - u_lo) / (u_hi - u_lo)).
template <class I>
I hodograph_hull(const BezierPieceView& piece, std::size_t c, int a, int b, const std::array<I, 4>& local) {
  const int n = piece.p - a, m = piece.q - b, cols = piece.q + 1;
  std::vector<I>& net = enclosure_scratch<I>();
  net.resize(static_cast<std::size_t>((n + 1) * (m + 1)));
  // Forward differences Delta^(a, b) of the net, in the interval type.
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      I sum(0.0);
      double binom_k = 1.0;
      for (int k = 0; k <= a; ++k, binom_k = binom_k * (a - k + 1) / k) {
        double binom_l = 1.0;
        for (int l = 0; l <= b; ++l, binom_l = binom_l * (b - l + 1) / l) {
          const double sign = ((a - k) + (b - l)) % 2 == 0 ? 1.0 : -1.0;
          sum = sum + I(sign * binom_k * binom_l) * I(piece.net[static_cast<std::size_t>((i + k) * cols + j + l)][c]);
        }
      }
      net[static_cast<std::size_t>(i * (m + 1) + j)] = sum;
    }
  const I &s0 = local[0], &s1 = local[1], &t0 = local[2], &t1 = local[3];
  for (int i = 0; i <= n; ++i) restrict_curve(net.data() + i * (m + 1), 1, m, t0, t1);
  for (int j = 0; j <= m; ++j) restrict_curve(net.data() + j, m + 1, n, s0, s1);
  double lo = net[0].lo(), hi = net[0].hi();
  for (const I& x : net) {
    lo = std::min<double>(lo, x.lo());
    hi = std::max<double>(hi, x.hi());
  }
  // d/du = (1 / width_u) d/ds: the hodograph's factor p! / (p - a)! / width^a.
  I scale(1.0);
  const I wu = I(piece.u_hi) - I(piece.u_lo), wv = I(piece.v_hi) - I(piece.v_lo);
  for (int k = 0; k < a; ++k) scale = scale * I(static_cast<double>(piece.p - k)) / wu;
  for (int l = 0; l < b; ++l) scale = scale * I(static_cast<double>(piece.q - l)) / wv;
  return I(lo, hi) * scale;
}

/// The hull of the projected points (w x / w, ...) of the piece restricted to the part; false
/// when a restricted weight may be <= 0 (a part beyond the piece, where the hull does not hold).
template <class I>
bool projected_hull(const BezierPieceView& piece, const std::array<I, 4>& local, std::array<I, 3>* out) {
  const int n = piece.p, m = piece.q;
  const std::size_t size = static_cast<std::size_t>((n + 1) * (m + 1));
  std::vector<I>& all = enclosure_scratch<I>();
  all.resize(4 * size);
  for (std::size_t c = 0; c < 4; ++c) {
    I* net = all.data() + c * size;
    for (std::size_t k = 0; k < size; ++k) net[k] = I(piece.net[k][c]);
    for (int i = 0; i <= n; ++i) restrict_curve(net + i * (m + 1), 1, m, local[2], local[3]);
    for (int j = 0; j <= m; ++j) restrict_curve(net + j, m + 1, n, local[0], local[1]);
  }
  for (std::size_t k = 0; k < size; ++k)
    if (!(all[3 * size + k].lo() > 0)) return false;
  for (std::size_t c = 0; c < 3; ++c) {
    double lo = 0, hi = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const I x = all[c * size + k] / all[3 * size + k];
      lo = k == 0 ? x.lo() : std::min<double>(lo, x.lo());
      hi = k == 0 ? x.hi() : std::max<double>(hi, x.hi());
    }
    (*out)[c] = I(lo, hi);
  }
  return true;
}

/// The enclosures of one piece over the part [u0, u1] x [v0, v1] of a box, partials to `depth`.
template <class I, std::size_t D>
void enclose_part(const BezierPieceView& piece, double u0, double u1, double v0, double v1, int depth,
                  PartEnclosure<I, D>* out) {
  const I wu = I(piece.u_hi) - I(piece.u_lo), wv = I(piece.v_hi) - I(piece.v_lo);
  const std::array<I, 4> local{(I(u0) - I(piece.u_lo)) / wu, (I(u1) - I(piece.u_lo)) / wu, (I(v0) - I(piece.v_lo)) / wv,
                               (I(v1) - I(piece.v_lo)) / wv};
  for (int order = 0; order <= depth; ++order)
    for (int b = 0; b <= order; ++b) {
      const int a = order - b;
      for (std::size_t c = 0; c < D; ++c)
        out->partial[c][static_cast<std::size_t>(partial_slot(a, b))] =
            a > piece.p || b > piece.q ? I(0.0) : hodograph_hull<I>(piece, c, a, b, local);
    }
  out->has_projected = D == 4 && projected_hull<I>(piece, local, &out->projected);
}

/// H_c(u, v) in T from the partials' enclosures over the part: the chain rule, one level of T's
/// gradients per order of partials (u, v carry their derivatives; their values lie in the part).
template <class T, class I, std::size_t D>
T compose(const PartEnclosure<I, D>& e, std::size_t c, int a, int b, const T& u, const T& v) {
  if constexpr (Enclosure<T>::depth == 0) {
    return e.partial[c][static_cast<std::size_t>(partial_slot(a, b))];
  } else {
    T r;
    r.v = compose(e, c, a, b, u.v, v.v);
    const auto fu = compose(e, c, a + 1, b, u.v, v.v), fv = compose(e, c, a, b + 1, u.v, v.v);
    for (std::size_t i = 0; i < r.d.size(); ++i) r.d[i] = fu * u.d[i] + fv * v.d[i];
    return r;
  }
}

/// The parts of [lo, hi] in the pieces of one direction: f(piece index, part lo, part hi) for
/// each piece met. `breaks` are the pieces' ends; a periodic direction wraps the box into
/// [breaks.front(), breaks.back()], otherwise the end pieces continue beyond the ends.
template <class F>
void for_each_part(std::span<const double> breaks, bool periodic, double lo, double hi, F f) {
  const int pieces = static_cast<int>(breaks.size()) - 1;
  const double first = breaks.front(), last = breaks.back(), width = last - first;
  const auto in_range = [&](double a, double b) {
    // Pieces i with [breaks[i], breaks[i + 1]] meeting [a, b]; the end pieces reach to infinity.
    int i = static_cast<int>(std::upper_bound(breaks.begin() + 1, breaks.end() - 1, a) - breaks.begin()) - 1;
    if (i > 0 && breaks[static_cast<std::size_t>(i)] == a) --i;  // a on a break: the piece before it too
    for (; i < pieces; ++i) {
      const double plo = i == 0 ? a : std::max(a, breaks[static_cast<std::size_t>(i)]);
      const double phi = i == pieces - 1 ? b : std::min(b, breaks[static_cast<std::size_t>(i) + 1]);
      if (plo > phi) break;
      f(i, plo, phi);
    }
  };
  if (!periodic) return in_range(lo, hi);
  const double k0 = std::floor((lo - first) / width), k1 = std::floor((hi - first) / width);
  // A box of a period or more (or so far out that whole periods are not resolved) meets every piece.
  if (!(hi - lo < width) || !(std::abs(k0) < 0x1p40 && std::abs(k1) < 0x1p40)) return in_range(first, last);
  // Whole periods k with [first + k w, first + (k + 1) w] meeting [lo, hi]: at most two.
  for (double k = k0; k <= k1; ++k) {
    const double a = std::max(lo - k * width, first), b = std::min(hi - k * width, last);
    // The shift is rounded: widen by an ulp each way (a part a little wider is still sound).
    if (a <= b) in_range(std::max(first, std::nextafter(a, -INFINITY)), std::min(last, std::nextafter(b, INFINITY)));
  }
}

/// A grid of Bezier pieces: a B-spline's extraction, or one Bezier patch.
struct PieceGrid {
  std::span<const double> breaks_u, breaks_v;
  const std::array<double, 4>* nets = nullptr;
  int p = 0, q = 0;
  bool periodic_u = false, periodic_v = false;

  BezierPieceView view(int i, int j) const {
    const int pieces_v = static_cast<int>(breaks_v.size()) - 1;
    const std::size_t at = static_cast<std::size_t>((i * pieces_v + j) * (p + 1) * (q + 1));
    return {nets + at,
            p,
            q,
            breaks_u[static_cast<std::size_t>(i)],
            breaks_u[static_cast<std::size_t>(i) + 1],
            breaks_v[static_cast<std::size_t>(j)],
            breaks_v[static_cast<std::size_t>(j) + 1]};
  }
};

/// An enclosure of F(u, v) and of its derivatives in T over the box of u's and v's values: the
/// hull over the parts of the box in the grid's pieces (see the header).
template <class T>
Vec3T<T> enclose_on_pieces(const PieceGrid& grid, bool rational, const T& u, const T& v) {
  using I = typename Enclosure<T>::Scalar;
  constexpr int depth = Enclosure<T>::depth;
  static_assert(depth <= kMaxEnclosureDepth);
  const I& ub = innermost(u);
  const I& vb = innermost(v);
  Vec3T<T> hull;
  bool first = true;
  const auto part = [&]<std::size_t D>(int i, double u0, double u1, int j, double v0, double v1) {
    PartEnclosure<I, D> e;
    enclose_part<I, D>(grid.view(i, j), u0, u1, v0, v1, depth, &e);
    T uu = u, vv = v;
    innermost(uu) = I(u0, u1);
    innermost(vv) = I(v0, v1);
    std::array<T, D> h;
    for (std::size_t c = 0; c < D; ++c) h[c] = compose(e, c, 0, 0, uu, vv);
    Vec3T<T> f = {h[0], h[1], h[2]};
    if constexpr (D == 4) {
      f = {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
      if (e.has_projected) {
        T* xyz[3] = {&f.x, &f.y, &f.z};
        for (std::size_t c = 0; c < 3; ++c) {
          I& value = innermost(*xyz[c]);
          value =
              I(std::max<double>(value.lo(), e.projected[c].lo()), std::min<double>(value.hi(), e.projected[c].hi()));
          if (!(value.lo() <= value.hi())) value = e.projected[c];  // disjoint only by rounding
        }
      }
    }
    hull = first ? f : Vec3T<T>{enclosure_hull(hull.x, f.x), enclosure_hull(hull.y, f.y), enclosure_hull(hull.z, f.z)};
    first = false;
  };
  for_each_part(grid.breaks_u, grid.periodic_u, ub.lo(), ub.hi(), [&](int i, double u0, double u1) {
    for_each_part(grid.breaks_v, grid.periodic_v, vb.lo(), vb.hi(), [&](int j, double v0, double v1) {
      if (rational)
        part.template operator()<4>(i, u0, u1, j, v0, v1);
      else
        part.template operator()<3>(i, u0, u1, j, v0, v1);
    });
  });
  return hull;
}

}  // namespace ssimarch::internal
