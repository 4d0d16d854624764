// Traced curves for ParaView (VTK XML, io/vtk_xml.hpp; docs/output-format.md "ParaView / VTK"):
// the curves of every intersection as polylines with per-point data, the vertices of the curve
// networks (singular points, isolated points, curve ends) as a second data set, and a multiblock
// file holding both.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "ssimarch/io/vtk_xml.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

/// The curves: one polyline per traced curve (a closed curve's last point repeats its first).
/// Point data: "params" (the unknowns of H, 4 components, NaN-padded: u,v,p,q | u,v | x,y,z),
/// "t" (unit tangent), "kappa", "tau" (NaN without the geometry option or where undetermined),
/// "arc_length" (from the curve's first point, the circular-arc estimate of the curve's length),
/// "intersection" (index of the run), "branch" (the curve's index in its intersection).
/// Cell data per polyline: "intersection", "branch", "closed" (0/1), "length".
/// Field data: "intersection_names".
VtkPolyData curves_poly_data(const std::vector<IntersectionRun>& runs);

/// The vertices of each run's curve network (network/curve_network.hpp), one vertex cell each.
/// Point data: "kind" (0 singular point, 1 isolated point, 2 boundary end, 3 interior end),
/// "type" (the singular point's type, e.g. "node", or the kind's name for ends), "params",
/// "intersection". Field data: "kind_names", "intersection_names".
VtkPolyData network_vertices_poly_data(const std::vector<IntersectionRun>& runs);

/// The three files of `ssimarch trace --format vtp -o P`: for P = DIR/STEM.vtp or DIR/STEM.vtm,
/// DIR/STEM.vtp (curves), DIR/STEM_points.vtp (vertices) and DIR/STEM.vtm (both as blocks
/// "curves" and "points").
struct VtpTraceFiles {
  std::filesystem::path curves, points, multiblock;
};
VtpTraceFiles vtp_trace_files(const std::filesystem::path& output);

/// The multiblock file's text, naming the other two relative to its folder.
void write_trace_vtm(std::ostream& out, const VtpTraceFiles& files);

}  // namespace ssimarch
