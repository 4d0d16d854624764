#include "ssimarch/network/rotation_index.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

namespace ssimarch {

namespace {

using Vec2 = Eigen::Vector2d;

// The curve's points in the parameter plane of its first surface, periodic unknowns unwrapped
// so that the polygon is continuous (P.difference reduces each step to half a period).
std::vector<Vec2> parameter_plane(const Problem& P, const TracedCurve& c) {
  std::vector<Vec2> q;
  q.push_back(Vec2(c.points[0].x[0], c.points[0].x[1]));
  for (std::size_t i = 1; i < c.points.size(); ++i) {
    const VecX d = P.difference(c.points[i - 1].x, c.points[i].x);
    q.push_back(q.back() + Vec2(d[0], d[1]));
  }
  return q;
}

// The curve's 3D points projected on the plane of their two largest principal axes
// (docs/math/rotation_index_plane.md): a choice that depends on the curve alone.
std::vector<Vec2> principal_plane(const TracedCurve& c) {
  const std::size_t n = c.points.size() - 1;  // the closing point repeats the first
  Vec3 mean = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) mean += c.points[i].p;
  mean /= static_cast<double>(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) cov += (c.points[i].p - mean) * (c.points[i].p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // eigenvalues ascending
  const Vec3 e1 = eig.eigenvectors().col(2), e2 = eig.eigenvectors().col(1);
  std::vector<Vec2> q;
  for (const CurvePoint& p : c.points) q.push_back(Vec2((p.p - mean).dot(e1), (p.p - mean).dot(e2)));
  return q;
}

double signed_angle(const Vec2& a, const Vec2& b) { return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)); }

}  // namespace

RotationIndex rotation_index(const Problem& P, const TracedCurve& c, const std::vector<bool>& corner) {
  RotationIndex r;
  const bool implicit = P.kind() == PairKind::kImplicitImplicit;
  r.plane = implicit ? "principal axes" : "u,v";
  if (!c.closed || c.points.size() < 4) {
    r.note = c.closed ? "too few points" : "open curve";
    return r;
  }
  const std::vector<Vec2> q = implicit ? principal_plane(c) : parameter_plane(P, c);
  // Chords with their start index; chords shorter than rounding (repeated points at a
  // singular point) carry no direction and are skipped.
  double extent = 0;
  for (const Vec2& v : q) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  std::vector<std::pair<Vec2, std::size_t>> chords;
  for (std::size_t i = 0; i + 1 < q.size(); ++i)
    if ((q[i + 1] - q[i]).norm() > 1e-12 * std::max(1.0, extent)) chords.push_back({q[i + 1] - q[i], i + 1});
  if (chords.size() < 3) {
    r.note = "the curve is a point in the plane";
    return r;
  }
  // Signed exterior angles at every vertex of the closed polygon (Def. 2, eqs 2.15-2.16); the
  // one at the start point is the closing angle that the index condition bounds (sec. 6.3).
  double closing = 0;
  for (std::size_t k = 0; k < chords.size(); ++k) {
    const auto& [a, at] = chords[k];
    const Vec2& b = chords[(k + 1) % chords.size()].first;
    double theta = signed_angle(a, b);
    const std::size_t vertex = at % (q.size() - 1);
    const bool at_corner = vertex < corner.size() && corner[vertex];
    // A reversal at a singular point (a cusp) is the exterior angle pi of Def. 2, whose range
    // (-pi, pi] takes the reversal as +pi; the polygon's chords give +-pi by which side they
    // approach from, which is rounding, not geometry.
    if (std::abs(theta) > kRotationMaxChordTurn && at_corner) theta = M_PI;
    if (std::abs(theta) > kRotationMaxChordTurn && !at_corner) {
      r.note = "the curve folds in the " + r.plane + " plane near point " + std::to_string(at) +
               " (its tangent there has no direction in the plane)";
      return r;
    }
    if (k + 1 == chords.size() && !at_corner) closing = theta;  // a start at a singular point is a corner
    r.turning += theta;
  }
  if (std::abs(closing) >= kRotationIndexSigma) {
    r.note = "the curve closes with a corner of " + std::to_string(closing) + " rad at its start";
    return r;
  }
  r.index = static_cast<int>(std::lround(r.turning / (2 * M_PI)));
  return r;
}

}  // namespace ssimarch
