// ssimarch batch JOBS.json: many scenes, or every surface pair of a model, traced as one job on
// every core, and under mpirun (SSIMARCH_MPI=ON) on every rank; one merged JSON output in input
// order (docs/scene-format.md "Batch files", docs/output-format.md "Batch output",
// docs/scaling.md).
#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>

#include "batch_ranks.hpp"
#include "commands.hpp"
#include "run_progress.hpp"
#include "run_budget.hpp"
#include "ssimarch/core/thread_pool.hpp"
#include "ssimarch/io/batch_file.hpp"
#include "ssimarch/io/output_files.hpp"

namespace ssimarch::cli {

namespace {

struct BatchArgs {
  std::string jobs;
  std::string output = "-";
  unsigned threads = 0;
  bool quiet = false;
  std::string timings;
};

// This rank's share: units taken from `ranks` until none is left, each as compact JSON text.
// Progress (`meter`): units are handed out in input order by one counter (every rank's), so the
// highest unit finished here tells how far the whole batch has got, on rank 0 as on one process.
std::vector<UnitResult> run_share(const Batch& batch, unsigned threads, BatchRanks* ranks, RankLoad* load,
                                  ProgressMeter* meter) {
  std::vector<UnitResult> local;
  std::mutex m;
  std::size_t reached = 0;
  // The units' own stages (start points of one intersection) are not shown: the calling thread's
  // reports go nowhere while the batch's units run (core/progress.hpp scopes nest).
  const ProgressScope units_silent(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  run_batch_units(batch, threads, [ranks] { return ranks->next(); }, [&](std::size_t u, BatchOutcome&& outcome) {
    UnitResult r{u, ranks->rank(), outcome.seconds, outcome.cpu_seconds, batch_unit_json(batch, u, outcome).dump()};
    std::lock_guard<std::mutex> lock(m);
    reached = std::max(reached, u + 1);
    meter->report("batch", static_cast<double>(reached), static_cast<double>(batch.units.size()));
    load->units += 1;
    load->busy_s += r.wall_s;
    load->cpu_s += r.cpu_s;
    local.push_back(std::move(r));
  });
  load->finish_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return local;
}

// Per rank: units, busy and CPU time, finish time; and the spread of the CPU times (docs/scaling.md).
void print_loads(const std::vector<RankLoad>& loads, unsigned threads) {
  double most = 0, total = 0, last = 0;
  for (std::size_t r = 0; r < loads.size(); ++r) {
    const RankLoad& l = loads[r];
    std::cerr << "  rank " << r << ": " << l.units << " units, busy " << std::setprecision(4) << l.busy_s << " s, CPU " << l.cpu_s
              << " s (" << threads << " threads), done at " << l.finish_s << " s\n";
    most = std::max(most, l.cpu_s);
    total += l.cpu_s;
    last = std::max(last, l.finish_s);
  }
  const double mean = total / static_cast<double>(loads.size());
  std::cerr << "  load balance: max CPU / mean CPU - 1 = " << std::setprecision(3) << (mean > 0 ? most / mean - 1 : 0.0) << "; "
            << std::setprecision(6) << last << " s wall\n";
}

// --timings: one CSV row per unit (its cost; the input of the model of docs/scaling.md).
void write_timings(const Batch& batch, const std::vector<UnitResult>& units, const std::string& path, OutputFiles* files) {
  std::ostream& out = files->open(path);
  out << "unit,job,intersection,rank,wall_s,cpu_s,bytes\n" << std::setprecision(9);
  for (const UnitResult& r : units) {
    const BatchUnit& u = batch.units[r.unit];
    out << r.unit << "," << u.job << "," << batch.jobs[u.job].intersections[u.intersection].name << "," << r.rank << "," << r.wall_s
        << "," << r.cpu_s << "," << r.text.size() << "\n";
  }
}

int run_batch_command(const BatchArgs& a) {
  if (a.threads > 0) set_thread_count(a.threads);
  const Batch batch = load_batch(a.jobs, input_limits());
  std::unique_ptr<BatchRanks> ranks = start_batch_ranks();
  const unsigned threads = a.threads > 0 ? a.threads : ranks->default_threads();
  set_thread_count(threads);
  RankLoad load;
  RunProgress progress(a.quiet || ranks->rank() != 0);  // rank 0's bar only
  auto local = run_share(batch, threads, ranks.get(), &load, &progress.meter());
  progress.meter().close();
  auto [units, loads] = ranks->gather(std::move(local), batch.units.size(), load);
  int status = 0;
  if (ranks->rank() == 0) {
    try {
      std::vector<nlohmann::json> entries;
      for (const UnitResult& u : units) entries.push_back(nlohmann::json::parse(u.text));
      const nlohmann::json result = batch_result_json(batch, entries);
      OutputFiles files;
      files.open(a.output) << result.dump(1) << "\n";
      if (!a.timings.empty()) write_timings(batch, units, a.timings, &files);
      files.commit();
      const nlohmann::json& s = result.at("summary");
      if (!a.quiet) {
        std::cerr << "batch: " << s.at("jobs") << " jobs (" << s.at("failed_jobs") << " failed), " << s.at("intersections")
                  << " intersections (" << s.at("failed_intersections") << " failed, " << s.at("incomplete")
                  << " incomplete), " << s.at("curves") << " curves; " << ranks->size() << " rank(s)\n";
        print_loads(loads, threads);
      }
      status = batch_result_complete(result) ? 0 : 1;
    } catch (const std::exception& e) {
      std::cerr << "ssimarch: error: " << e.what() << "\n";
      ranks->abort(2);
    }
  }
  return ranks->share_status(status);
}

}  // namespace

void add_batch_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* cmd = app.add_subcommand("batch", "Trace many scenes, or every surface pair of a model, as one job (threads; MPI ranks)");
  cmd->footer(
      "JOBS.json: {\"jobs\": [...]}, each job a scene file name, or {\"scene\": FILE or {scene}, \"pairs\": \"scene\" | "
      "\"all\", \"intersections\": [names], \"options\": {trace options}}; \"pairs\": \"all\" traces every pair of the "
      "scene's surfaces (docs/scene-format.md, \"Batch files\"). A bad job is reported with its error and the others go on.\n"
      "Output: JSON {\"jobs\": [{\"source\", \"intersections\": [...]} or {\"source\", \"error\"}], \"summary\"} in the "
      "order of the input, the same for any thread or rank count (docs/output-format.md, \"Batch output\").\n"
      "MPI: in a build with SSIMARCH_MPI=ON, `mpirun -n N ssimarch batch JOBS.json` shares the intersections between "
      "the ranks one at a time (dynamic load balancing); rank 0 writes the output (docs/scaling.md).\n"
      "Exit status: 0 every job read and every intersection traced completely; 1 a job or intersection failed or is "
      "incomplete (see the summary); 2 an unusable batch file or output.");
  cmd->add_option("jobs", args->jobs, "Batch file (JSON)")->required();
  cmd->add_option("-o,--output", args->output, "Output file; '-' for standard output (default)");
  cmd->add_option("--threads", args->threads,
                  "Threads per process (default: every core; under mpirun the node's cores divided among its ranks)");
  cmd->add_option("--timings", args->timings,
                  "Also write a CSV of every intersection's cost: unit, job, intersection, rank, wall_s, cpu_s, bytes");
  cmd->add_flag("-q,--quiet", args->quiet, "No summary and no progress on stderr");
  add_progress_option(cmd);
  add_budget_options(cmd);
  commands.add(cmd, [args] { return run_batch_command(*args); });
}

}  // namespace ssimarch::cli
