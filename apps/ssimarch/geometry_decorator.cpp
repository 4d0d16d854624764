// --geometry METHOD: the curve's differential geometry at every output point (issue 4).
#include <algorithm>

#include "commands.hpp"
#include "ssimarch/geometry/intersection_geometry.hpp"
#include "trace_output.hpp"

namespace ssimarch::cli {

PointDecorator make_geometry_decorator(const std::vector<IntersectionRun>& runs) {
  bool any = false;
  for (const auto& r : runs) {
    if (!r.spec.extra_options.contains("geometry")) continue;
    GeometryMethod m;
    std::string name = r.spec.extra_options["geometry"].get<std::string>();
    if (!parse(name, &m))
      throw CliError("geometry: unknown method \"" + name + "\" (known: " + method_names() + ")");
    any = true;
  }
  if (!any) return {};
  return [](const IntersectionRun& run, const TracedCurve& curve, std::size_t i, nlohmann::json* point) {
    if (!run.spec.extra_options.contains("geometry")) return;
    GeometryMethod method;
    parse(run.spec.extra_options["geometry"].get<std::string>(), &method);
    GeometryContext ctx;
    // Neighbours along the traced curve (closed curves wrap; the closing point repeats the first).
    const std::size_t n = curve.points.size();
    const std::size_t m = curve.closed && n > 1 ? n - 1 : n;
    const std::size_t k = (curve.closed && i + 1 == n) ? 0 : std::min(i, m - 1);  // the closing point is point 0
    for (std::size_t back = 3; back >= 1; --back) {
      if (k >= back) ctx.previous.push_back(curve.points[k - back].x);
      else if (curve.closed && m > back) ctx.previous.push_back(curve.points[m + k - back].x);
    }
    if (k + 1 < m) ctx.next.push_back(curve.points[k + 1].x);
    else if (curve.closed && m > 1) ctx.next.push_back(curve.points[0].x);
    ctx.orientation = curve.points[i].t;
    CurveGeometry g = evaluate_geometry(run.problem, curve.points[i].x, method, ctx);
    auto v = [](const Vec3& a) {
      return a.allFinite() ? nlohmann::json::array({a.x(), a.y(), a.z()}) : nlohmann::json(nullptr);
    };
    auto s = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
    (*point)["t"] = v(g.t);
    (*point)["n"] = v(g.n);
    (*point)["b"] = v(g.b);
    (*point)["kappa"] = s(g.kappa);
    (*point)["tau"] = s(g.tau);
    (*point)["kappa_prime"] = s(g.kappa_prime);
    (*point)["theta"] = s(g.theta);
    (*point)["geometry_status"] = std::string(to_string(g.status));
  };
}

}  // namespace ssimarch::cli
