// Traced curves as VTK PolyData (see vtp_writer.hpp).
#include "ssimarch/io/vtp_writer.hpp"

#include <limits>

#include "ssimarch/march/arc_length.hpp"

namespace ssimarch {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kParamComponents = 4;  // the most unknowns of any pair kind (parametric-parametric)

void append_params(const VecX& x, std::vector<double>* out) {
  for (int i = 0; i < kParamComponents; ++i) out->push_back(i < x.size() ? x[i] : kNaN);
}

std::vector<std::string> intersection_names(const std::vector<IntersectionRun>& runs) {
  std::vector<std::string> names;
  for (const IntersectionRun& r : runs) names.push_back(r.spec.name);
  return names;
}

// Per-point arrays of the curves block, filled curve by curve.
struct CurveArrays {
  std::vector<double> params, t, kappa, tau, arc;
  std::vector<std::int32_t> intersection, branch;
  std::vector<std::int32_t> cell_intersection, cell_branch, cell_closed;
  std::vector<double> cell_length;
};

void add_curve(const IntersectionRun& run, int ri, std::size_t ci, VtkPolyData* d, CurveArrays* a) {
  const TracedCurve& c = run.result.curves[ci];
  const std::vector<CurveGeometry>* g = ci < run.geometry.size() ? &run.geometry[ci] : nullptr;
  std::vector<std::int64_t> line;
  double s = 0;
  // The curve's own segment lengths (march/arc_length.hpp, recorded_segment_lengths).
  const std::vector<double> segments = recorded_segment_lengths(c);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const CurvePoint& p = c.points[i];
    if (i > 0) s += segments[i - 1];
    line.push_back(static_cast<std::int64_t>(d->points.size()));
    d->points.push_back(p.p);
    append_params(p.x, &a->params);
    a->t.insert(a->t.end(), {p.t.x(), p.t.y(), p.t.z()});
    a->kappa.push_back(g && i < g->size() ? (*g)[i].kappa : kNaN);
    a->tau.push_back(g && i < g->size() ? (*g)[i].tau : kNaN);
    a->arc.push_back(s);
    a->intersection.push_back(ri);
    a->branch.push_back(static_cast<std::int32_t>(ci));
  }
  d->lines.push_back(std::move(line));
  a->cell_intersection.push_back(ri);
  a->cell_branch.push_back(static_cast<std::int32_t>(ci));
  a->cell_closed.push_back(c.closed ? 1 : 0);
  a->cell_length.push_back(c.length);
}

}  // namespace

VtkPolyData curves_poly_data(const std::vector<IntersectionRun>& runs) {
  VtkPolyData d;
  CurveArrays a;
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (std::size_t c = 0; c < runs[r].result.curves.size(); ++c) add_curve(runs[r], static_cast<int>(r), c, &d, &a);
  d.point_data = {VtkArray::real("params", std::move(a.params), kParamComponents), VtkArray::real("t", std::move(a.t), 3),
                  VtkArray::real("kappa", std::move(a.kappa)), VtkArray::real("tau", std::move(a.tau)),
                  VtkArray::real("arc_length", std::move(a.arc)), VtkArray::integer("intersection", std::move(a.intersection)),
                  VtkArray::integer("branch", std::move(a.branch))};
  d.cell_data = {VtkArray::integer("intersection", std::move(a.cell_intersection)),
                 VtkArray::integer("branch", std::move(a.cell_branch)), VtkArray::integer("closed", std::move(a.cell_closed)),
                 VtkArray::real("length", std::move(a.cell_length))};
  d.field_data = {VtkArray::text("intersection_names", intersection_names(runs))};
  return d;
}

VtkPolyData network_vertices_poly_data(const std::vector<IntersectionRun>& runs) {
  VtkPolyData d;
  std::vector<double> params;
  std::vector<std::int32_t> kind, intersection;
  std::vector<std::string> type;
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (const NetworkVertex& v : runs[r].network.vertices) {
      d.verts.push_back(static_cast<std::int64_t>(d.points.size()));
      d.points.push_back(v.p);
      append_params(v.x, &params);
      kind.push_back(static_cast<std::int32_t>(v.kind));
      type.push_back(v.type.empty() ? std::string(to_string(v.kind)) : v.type);
      intersection.push_back(static_cast<std::int32_t>(r));
    }
  d.point_data = {VtkArray::integer("kind", std::move(kind)), VtkArray::text("type", std::move(type)),
                  VtkArray::real("params", std::move(params), kParamComponents),
                  VtkArray::integer("intersection", std::move(intersection))};
  std::vector<std::string> kind_names;
  for (VertexKind k : {VertexKind::kSingularPoint, VertexKind::kIsolatedPoint, VertexKind::kBoundaryEnd, VertexKind::kInteriorEnd})
    kind_names.emplace_back(to_string(k));
  d.field_data = {VtkArray::text("kind_names", std::move(kind_names)),
                  VtkArray::text("intersection_names", intersection_names(runs))};
  return d;
}

VtpTraceFiles vtp_trace_files(const std::filesystem::path& output) {
  const std::filesystem::path dir = output.parent_path();
  const std::string stem = output.stem().string();
  return {dir / (stem + ".vtp"), dir / (stem + "_points.vtp"), dir / (stem + ".vtm")};
}

void write_trace_vtm(std::ostream& out, const VtpTraceFiles& files) {
  write_vtm(out, {{"curves", files.curves.filename().string()}, {"points", files.points.filename().string()}});
}

}  // namespace ssimarch
