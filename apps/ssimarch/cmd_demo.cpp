// ssimarch demo: traces the built-in examples and writes JSON, CSV, OBJ, SVG and the viewer's HTML pages
// under out/demo/.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "demo_scenes.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/svg_plot.hpp"
#include "ssimarch/io/porosity_demo.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "trace_output.hpp"
#include "viewer_page.hpp"

namespace ssimarch::cli {

namespace {

struct DemoArgs {
  std::string out = "out/demo";
  bool skip_porosity = false;
};

void run_demo(const DemoArgs& a) {
  namespace fs = std::filesystem;
  fs::path dir(a.out);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw CliError(a.out + ": cannot create the output directory: " + ec.message());
  std::vector<IntersectionRun> runs;
  OutputFiles files;  // scenes and pictures, all or nothing (io/output_files.hpp)
  std::cout << "ssimarch demo: tracing the built-in examples into " << dir.string() << "/\n\n";
  const bool pages = !viewer_script().empty();
  for (const DemoScene& d : demo_scenes()) {
    files.open(dir / (d.name + ".scene.json")) << d.json << "\n";
    Scene scene = parse_scene(d.json, d.name + ".scene.json");
    const std::size_t first_run = runs.size();
    for (const auto& spec : scene.intersections) {
      runs.push_back(run_intersection(scene, spec));
      const IntersectionRun& r = runs.back();
      std::cout << "* " << d.title << "\n  " << r.result.curves.size() << " curve(s), " << r.result.stats.points << " points, "
                << std::fixed << std::setprecision(1) << r.result.stats.time_ms << " ms\n" << std::defaultfloat;
      for (std::size_t i = 0; i < r.result.curves.size(); ++i) {
        const auto& c = r.result.curves[i];
        std::cout << "  curve " << i << ": " << (c.closed ? "closed" : "open") << ", length " << std::setprecision(12) << c.length;
        if (i == 0 && d.exact_length > 0)
          std::cout << " (exact " << d.exact_length << ", relative error " << std::setprecision(2)
                    << std::fabs(c.length / d.exact_length - 1) << ")";
        std::cout << std::setprecision(6) << "\n";
      }
      write_svg(files.open(dir / (spec.name + ".svg")), r);
    }
    if (pages)
      write_trace_page(files.open(dir / (d.name + ".html")), {runs.begin() + static_cast<long>(first_run), runs.end()}, scene, d.name);
  }
  files.commit();
  write_runs(runs, OutputFormat::kJson, (dir / "curves.json").string());
  write_runs(runs, OutputFormat::kCsv, (dir / "curves.csv").string());
  write_runs(runs, OutputFormat::kObj, (dir / "curves.obj").string());
  std::cout << "\nwrote " << (dir / "curves.json").string() << ", curves.csv, curves.obj and one SVG per example ("
            << "3D view and parameter domains)"
            << (pages ? ", one HTML page per scene (the 3D viewer, docs/viewer.md)\n"
                      : "\nno HTML pages: this ssimarch was built without the viewer (docs/viewer.md)\n");
  if (!a.skip_porosity) {
    std::cout << "\n* packed bed of spheres: exact radial porosity profile\n";
    run_porosity_demo(dir / "porosity", std::cout, viewer_script());
  }
}

}  // namespace

void add_demo_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo", "Trace the built-in examples and write results and pictures");
  cmd->add_option("--out", args->out, "Output directory (default out/demo)");
  cmd->add_flag("--no-porosity", args->skip_porosity, "Skip the packed-bed porosity part");
  commands.add(cmd, [args] {
    run_demo(*args);
    return 0;
  });
}

}  // namespace ssimarch::cli
