#include <chrono>
#include <cmath>

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAPI_IntSS.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>

#include "peer_engines.hpp"

namespace peers {

using namespace ssimarch;

Outcome run_occt(const OcctPair& pair, const Surface& a, const Surface& b, double* ms) {
  Outcome out;
  *ms = NAN;
  if (pair.first.IsNull() || pair.second.IsNull()) {
    out.note = "no such variant";
    return out;
  }
  try {
    const auto t0 = std::chrono::steady_clock::now();
    GeomAPI_IntSS inter(pair.first, pair.second, 1e-7);
    *ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!inter.IsDone()) {
      out.note = "not done";
      return out;
    }
    out.curves = inter.NbLines();
    for (int i = 1; i <= inter.NbLines(); ++i) {
      const Handle(Geom_Curve) c = inter.Line(i);
      const double f = c->FirstParameter(), l = c->LastParameter();
      if (!std::isfinite(f) || !std::isfinite(l)) {
        out.note = "unbounded curve";
        continue;
      }
      GeomAdaptor_Curve ac(c, f, l);
      out.length += GCPnts_AbscissaPoint::Length(ac, f, l, 1e-10);
      const gp_Pnt p0 = c->Value(f), p1 = c->Value(l);
      if (c->IsClosed() || p0.Distance(p1) <= 1e-7) ++out.closed;
      for (int k = 0; k <= 200; ++k) {
        const gp_Pnt p = c->Value(f + (l - f) * k / 200.0);
        out.residual = std::max(out.residual, residual(a, b, Vec3(p.X(), p.Y(), p.Z())));
      }
    }
  } catch (const Standard_Failure& e) {
    out.note = std::string("exception: ") + e.GetMessageString();
  }
  return out;
}

}  // namespace peers
