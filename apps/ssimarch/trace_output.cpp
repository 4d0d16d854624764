#include "trace_output.hpp"

#include <iomanip>
#include <stdexcept>
#include <iostream>

#include "commands.hpp"
#include "ssimarch/core/contract.hpp"
#include "ssimarch/step/writer.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/svg_plot.hpp"
#include "ssimarch/io/trace_writers.hpp"
#include "ssimarch/io/vtp_writer.hpp"
#include "ssimarch/march/tracer.hpp"
#include "viewer_page.hpp"

namespace ssimarch::cli {

OutputFormat parse_format(const std::string& s) {
  if (s == "json") return OutputFormat::kJson;
  if (s == "csv") return OutputFormat::kCsv;
  if (s == "obj") return OutputFormat::kObj;
  if (s == "svg") return OutputFormat::kSvg;
  if (s == "step") return OutputFormat::kStep;
  if (s == "vtp") return OutputFormat::kVtp;
  if (s == "vtp-ascii") return OutputFormat::kVtpAscii;
  if (s == "html") return OutputFormat::kHtml;
  throw CliError("--format: unknown format \"" + s + "\" (known: json, csv, obj, svg, step, vtp, vtp-ascii, html)");
}

OutputFormat format_from_path(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  if (e == ".csv") return OutputFormat::kCsv;
  if (e == ".obj") return OutputFormat::kObj;
  if (e == ".svg") return OutputFormat::kSvg;
  if (e == ".step" || e == ".stp") return OutputFormat::kStep;
  if (e == ".vtp" || e == ".vtm") return OutputFormat::kVtp;
  if (e == ".html" || e == ".htm") return OutputFormat::kHtml;
  if (e == ".json" || e.empty()) return OutputFormat::kJson;
  // Issue 29: `-o curves.vtk` wrote JSON under a name that promises another format.
  throw CliError("-o " + p.string() + ": the extension \"" + e +
                 "\" names no output format (known: .json, .csv, .obj, .svg, .step/.stp, .vtp/.vtm, .html/.htm; "
                 "or give --format)");
}

void write_runs(const std::vector<IntersectionRun>& runs, OutputFormat format, const std::string& path,
                const Scene* scene) {
  OutputFiles files;  // all files or none (io/output_files.hpp)
  if (format == OutputFormat::kSvg) {
    if (path == "-" && runs.size() != 1)
      throw CliError("SVG to standard output needs exactly one intersection (use --intersection NAME or -o FILE.svg)");
    const std::filesystem::path p(path);
    for (const auto& r : runs) {
      std::filesystem::path file = runs.size() == 1 ? p : p.parent_path() / (p.stem().string() + "_" + r.spec.name + ".svg");
      write_svg(files.open(file), r);
    }
    files.commit();
    return;
  }
  if (format == OutputFormat::kVtp || format == OutputFormat::kVtpAscii) {
    if (path == "-") throw CliError("--format vtp writes three files: give -o FILE.vtp (or FILE.vtm)");
    const VtkEncoding encoding = format == OutputFormat::kVtp ? VtkEncoding::kBase64 : VtkEncoding::kAscii;
    const VtpTraceFiles vtp = vtp_trace_files(path);
    write_vtp(files.open(vtp.curves), curves_poly_data(runs), encoding);
    write_vtp(files.open(vtp.points), network_vertices_poly_data(runs), encoding);
    write_trace_vtm(files.open(vtp.multiblock), vtp);
    files.commit();
    return;
  }
  std::ostream& out = files.open(path);
  switch (format) {
    case OutputFormat::kJson: write_json(out, runs); break;
    case OutputFormat::kCsv: write_csv(out, runs); break;
    case OutputFormat::kObj: write_obj(out, runs); break;
    case OutputFormat::kStep: write_step(out, runs, scene); break;
    case OutputFormat::kHtml:
      SSIMARCH_EXPECTS(scene, "write_runs: an HTML page needs the scene");
      write_trace_page(out, runs, *scene, runs.size() == 1 ? runs[0].spec.name : scene->source);
      break;
    case OutputFormat::kSvg:
    case OutputFormat::kVtp:
    case OutputFormat::kVtpAscii: break;
  }
  files.commit();
}

void print_summary(const std::vector<IntersectionRun>& runs) {
  for (const auto& r : runs) {
    const auto& s = r.result.stats;
    // The points the curves hold (what the output has); the tracer's accepted steps, which count
    // the points of marches that were joined or dropped too, are the work (issue 29: the two were
    // printed as one number that disagreed with the curves').
    std::size_t on_curves = 0;
    for (const TracedCurve& c : r.result.curves) on_curves += c.points.size();
    std::cerr << r.spec.name << ": " << r.result.curves.size() << " curve(s), " << on_curves
              << " points; work: " << s.points << " accepted and " << s.rejected_steps << " rejected steps, "
              << s.time_ms << " ms\n";
    const StartPointSearch& sp = r.result.start_search;
    std::cerr << "  start points: " << to_string(sp.method) << (sp.certified ? ", certified" : ", not certified");
    if (sp.method == StartSearchMethod::kCertified)
      std::cerr << " (" << sp.boxes << " boxes, " << sp.uncertain_regions.size() << " uncertain regions, " << sp.time_ms << " ms)";
    if (sp.certified && r.result.curves.empty() && r.result.isolated_points.empty()) std::cerr << "; no intersection";
    std::cerr << (sp.note.empty() ? "" : "; " + sp.note) << "\n";
    for (std::size_t i = 0; i < r.result.curves.size(); ++i) {
      const auto& c = r.result.curves[i];
      std::cerr << "  curve " << i << ": " << (c.closed ? "closed" : "open") << ", length " << std::setprecision(12) << c.length
                << ", " << c.points.size() << " points";
      if (!c.closed) std::cerr << "; ends: " << to_string(c.start_end) << " / " << to_string(c.end_end);
      std::cerr << std::setprecision(6) << "\n";
      if (!c.closed) {
        if (!c.start_message.empty()) std::cerr << "    start: " << c.start_message << "\n";
        if (!c.end_message.empty()) std::cerr << "    end: " << c.end_message << "\n";
      }
    }
    for (const SingularPointReport& p : r.result.isolated_points)
      std::cerr << "  isolated point: " << describe_point(p.p) << " (" << to_string(p.type) << ")\n";
    for (const auto& w : r.result.warnings) std::cerr << "  warning: " << w << "\n";
  }
}

}  // namespace ssimarch::cli
