// Frames and trims follow shared/peers/cases.jsonl and, for the occt_* cases, the DRAW scripts of
// OpenCASCADE's tests/lowalgos/intss (bug21494_2, bug24694_7, bug28222_2, bug33244).
#include "occt_surfaces.hpp"

#include <cmath>
#include <functional>
#include <map>

#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Ax3.hxx>

#include "occt_knot_surface.hpp"

namespace peers {

namespace {

using S = Handle(Geom_Surface);

gp_Ax3 ax3(double x, double y, double z, double dx, double dy, double dz) { return gp_Ax3(gp_Pnt(x, y, z), gp_Dir(dx, dy, dz)); }

S trim_v(const S& s, double v0, double v1) { return new Geom_RectangularTrimmedSurface(s, v0, v1, Standard_False); }
S trim_uv(const S& s, double u0, double u1, double v0, double v1) { return new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1); }
S sphere(double x, double y, double z, double r, const gp_Dir& axis = gp::DZ()) {
  return new Geom_SphericalSurface(gp_Ax3(gp_Pnt(x, y, z), axis), r);
}
S cylinder(const gp_Ax3& a, double r, double v0, double v1) { return trim_v(new Geom_CylindricalSurface(a, r), v0, v1); }
S plane(const gp_Ax3& a, double half) { return trim_uv(new Geom_Plane(a), -half, half, -half, half); }
S bspline(const S& s) { return GeomConvert::SurfaceToBSplineSurface(s); }

// x^2/a^2 + y^2/b^2 + z^2/c^2 = 1: the unit sphere's rational B-spline with scaled poles (an affine
// map of the poles keeps a rational B-spline exact).
S ellipsoid(double a, double b, double c) {
  Handle(Geom_BSplineSurface) s = GeomConvert::SurfaceToBSplineSurface(sphere(0, 0, 0, 1));
  for (int i = 1; i <= s->NbUPoles(); ++i)
    for (int j = 1; j <= s->NbVPoles(); ++j) {
      const gp_Pnt p = s->Pole(i, j);
      s->SetPole(i, j, gp_Pnt(a * p.X(), b * p.Y(), c * p.Z()));
    }
  return s;
}

// Bernstein coefficients on [lo, hi] of the polynomial sum_k c[k] x^k (degree n = c.size() - 1):
// power coefficients in t = (x - lo)/(hi - lo), then b_i = sum_{j<=i} C(i,j)/C(n,j) a_j.
std::vector<double> bernstein(std::vector<double> c, double lo, double hi) {
  const int n = static_cast<int>(c.size()) - 1;
  auto binom = [](int m, int k) { double r = 1; for (int i = 1; i <= k; ++i) r = r * (m - k + i) / i; return r; };
  std::vector<double> a(c.size(), 0.0);  // x = lo + (hi - lo) t
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= k; ++j) a[j] += c[k] * binom(k, j) * std::pow(lo, k - j) * std::pow(hi - lo, j);
  std::vector<double> b(c.size(), 0.0);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= i; ++j) b[i] += binom(i, j) / binom(n, j) * a[j];
  return b;
}

// The graph z = g(u) + h(v) over [lo, hi]^2 as an exact Bezier patch (g, h polynomials of one degree).
S graph(const std::vector<double>& g, const std::vector<double>& h, double lo, double hi) {
  const std::vector<double> bg = bernstein(g, lo, hi), bh = bernstein(h, lo, hi);
  const int n = static_cast<int>(g.size()) - 1;
  TColgp_Array2OfPnt poles(1, n + 1, 1, n + 1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      // The identity x = lo + (hi - lo) t has the Bernstein coefficients lo + (hi - lo) i / n.
      const double x = lo + (hi - lo) * i / n, y = lo + (hi - lo) * j / n;
      poles(i + 1, j + 1) = gp_Pnt(x, y, bg[i] + bh[j]);
    }
  return new Geom_BezierSurface(poles);
}

// Cone of OpenCASCADE (radius `r` at the reference plane, semi-angle `a`), trimmed to |axial
// distance from the apex| <= h.
S cone_about_apex(const gp_Ax3& frame, double a, double r, double h) {
  const double v_apex = -r / std::sin(a), dv = h / std::cos(a);
  return trim_v(new Geom_ConicalSurface(frame, a, r), v_apex - dv, v_apex + dv);
}

const std::map<std::string, std::function<OcctPair()>>& analytic_cases() {
  static const std::map<std::string, std::function<OcctPair()>> m = {
      {"viviani_thesis", [] { return OcctPair{sphere(0, 0, 0, 2), cylinder(ax3(0, -1, 0, 0, 0, 1), 1, -3, 3)}; }},
      {"viviani_thesis_xpole", [] { return OcctPair{sphere(0, 0, 0, 2, gp::DX()), cylinder(ax3(0, -1, 0, 0, 0, 1), 1, -3, 3)}; }},
      {"viviani_unit", [] { return OcctPair{sphere(0, 0, 0, 1), cylinder(ax3(0.5, 0, 0, 0, 0, 1), 0.5, -2, 2)}; }},
      {"torus_ruled_knot", [] { return OcctPair{knot_ruled_surface(), new Geom_ToroidalSurface(ax3(0, 0, 0, 0, 0, 1), 4, 1)}; }},
      {"plane_ellipsoid", [] { return OcctPair{plane(ax3(0, 0, 1, -1, 1, 1), 6), ellipsoid(1, 2, 3)}; }},
      {"two_cylinders", [] { return OcctPair{cylinder(ax3(0, 0, 0, 1, 0, 0), 1, -2, 2), cylinder(ax3(0, 0, 0, 0, 0, 1), 1, -2, 2)}; }},
      {"paraboloid_cylinder", [] { return OcctPair{graph({0, 0, 1}, {0, 0, 1}, -3, 3), cylinder(ax3(0, 0, 0, 0, 0, 1), 2, 0, 8)}; }},
      {"devil_curve", [] { return OcctPair{graph({0, 0, 2, 0, -1}, {0, 0, -1, 0, 1}, -2, 2), plane(ax3(0, 0, 0, 0, 0, 1), 3)}; }},
      {"sphere_plane_tangent", [] { return OcctPair{sphere(0, 0, 1, 1), plane(ax3(0, 0, 0, 0, 0, 1), 2)}; }},
      {"cylinder_plane_tangent", [] { return OcctPair{cylinder(ax3(0, 0, 1, 0, 1, 0), 1, -2, 2), plane(ax3(0, 0, 0, 0, 0, 1), 3)}; }},
      // bug21494_2: pcone c 15 0 10 (radius 15 at z = 0 shrinking to the apex at z = 10), psphere s 10.
      {"occt_bug21494_2", [] {
         const double a = -std::atan(1.5);
         return OcctPair{trim_v(new Geom_ConicalSurface(ax3(0, 0, 0, 0, 0, 1), a, 15), 0, 10 / std::cos(a)), sphere(0, 0, 0, 10)};
       }},
      // bug24694_7: cylinder cc 10; trimv tcc cc -20 20; sphere ss 10; convert s2 ss.
      {"occt_bug24694_7", [] { return OcctPair{cylinder(ax3(0, 0, 0, 0, 0, 1), 10, -20, 20), bspline(sphere(0, 0, 0, 10))}; }},
      // bug28222_2: cylinder s1 -35 13.37.. 30.58.. 0 -0.2588.. -0.9659.. 0 0.9659.. -0.2588.. 11 and
      // cylinder s2 0 0 0 1 0 0 0 0 -1 16.5 (location, axis, x direction, radius), trimmed here.
      {"occt_bug28222_2", [] {
         const gp_Ax3 f1(gp_Pnt(-35, 13.3706576198285, 30.5814570420266), gp_Dir(0, -0.258819045102521, -0.965925826289068),
                         gp_Dir(0, 0.965925826289068, -0.258819045102521));
         const gp_Ax3 f2(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0), gp_Dir(0, 0, -1));
         return OcctPair{cylinder(f1, 11, 10, 56), cylinder(f2, 16.5, -50, -20)};
       }},
      // bug33244: the script's two cones (location, axis, x direction, semi-angle, radius), trimmed here.
      {"occt_bug33244", [] {
         const gp_Ax3 f1(gp_Pnt(-1.11630646267172, -4.54487349779333, 13.2493435203532),
                         gp_Dir(-1.05794851588922e-07, -1.39278337794573e-08, 0.999999999999994),
                         gp_Dir(0.999999999999994, 5.91645678915759e-31, 1.05794851588922e-07));
         const gp_Ax3 f2(gp_Pnt(-2.08647872350287e-07, -5.78732475509323, 13.2493436211),
                         gp_Dir(-1.05794850062242e-07, -1.39278350756825e-08, 0.999999999999994),
                         gp_Dir(0.999999999999995, 0, 1.05794850062242e-07));
         return OcctPair{cone_about_apex(f1, 0.785398163360967, 0.560000000061149, 3),
                         cone_about_apex(f2, 0.785398163396248, 0.785398163396248, 3)};
       }},
  };
  return m;
}

}  // namespace

OcctPair occt_analytic(const std::string& name) {
  const auto& m = analytic_cases();
  const auto it = m.find(name);
  return it == m.end() ? OcctPair{} : it->second();
}

OcctPair occt_bspline(const std::string& name) {
  if (name == "ellipsoid_ellipsoid") return {ellipsoid(1.2, 1.6, 2), ellipsoid(0.9, 1.6, 2.5)};
  const OcctPair a = occt_analytic(name);
  if (a.first.IsNull()) return a;
  return {bspline(a.first), bspline(a.second)};
}

}  // namespace peers
