#include "ssimarch_bspline_scene.hpp"

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace peers {

namespace {

using nlohmann::json;

// {"bspline": {degree, knots_u, knots_v, control_points[u][v], weights[u][v]}} of an OpenCASCADE
// B-spline surface; a periodic direction is first made clamped (SetUNotPeriodic keeps the surface).
json bspline_json(const Handle(Geom_Surface) & s) {
  Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(s);
  if (b.IsNull()) throw std::runtime_error("peer_bench: the B-spline variant is not a Geom_BSplineSurface");
  b = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
  if (b->IsUPeriodic()) b->SetUNotPeriodic();
  if (b->IsVPeriodic()) b->SetVNotPeriodic();
  auto knots = [](const TColStd_Array1OfReal& k) {
    json out = json::array();
    for (int i = k.Lower(); i <= k.Upper(); ++i) out.push_back(k(i));
    return out;
  };
  TColStd_Array1OfReal ku(1, b->NbUPoles() + b->UDegree() + 1), kv(1, b->NbVPoles() + b->VDegree() + 1);
  b->UKnotSequence(ku);
  b->VKnotSequence(kv);
  json net = json::array(), weights = json::array();
  for (int i = 1; i <= b->NbUPoles(); ++i) {
    json row = json::array(), wrow = json::array();
    for (int j = 1; j <= b->NbVPoles(); ++j) {
      const gp_Pnt p = b->Pole(i, j);
      row.push_back({p.X(), p.Y(), p.Z()});
      wrow.push_back(b->Weight(i, j));
    }
    net.push_back(row);
    weights.push_back(wrow);
  }
  json d = {{"degree", {b->UDegree(), b->VDegree()}},
            {"knots_u", knots(ku)},
            {"knots_v", knots(kv)},
            {"control_points", net}};
  if (b->IsURational() || b->IsVRational()) d["weights"] = weights;
  return {{"bspline", d}};
}

}  // namespace

json ssimarch_bspline_scene_json(const std::string& scene_path, const OcctPair& bspline) {
  std::ifstream in(scene_path);
  json scene = json::parse(in);
  json it = scene.at("intersections").at(0);
  it.erase("as");
  const std::string a = it.at("surfaces").at(0), b = it.at("surfaces").at(1), name = it.at("name");
  scene["surfaces"][a] = bspline_json(bspline.first);
  scene["surfaces"][b] = bspline_json(bspline.second);
  json swapped = it;
  swapped["name"] = name + "_swapped";
  swapped["surfaces"] = {b, a};
  scene["intersections"] = {it, swapped};
  scene["description"] =
      "OpenCASCADE's GeomConvert B-splines of " + scene_path + " (bench/peers/ssimarch_bspline_scene.cpp)";
  return scene;
}

}  // namespace peers
