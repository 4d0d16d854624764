// A batch: many scenes, or every pair of a model's surfaces, traced as one job (issue 17 item 3;
// `ssimarch batch`, docs/scene-format.md "Batch files"). The unit of work is one intersection;
// units are numbered in input order (job by job, each job's intersections in order), and each
// unit's outcome is kept under its number, so a batch's result does not depend on which thread
// or MPI rank ran which unit. io/batch_file.hpp reads a batch file into this model.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/pipeline/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

/// One entry of a batch: a scene and the intersections of it to trace, or the error that made
/// the entry unusable (a missing or invalid scene): that entry fails, the others go on.
struct BatchJob {
  std::string source;                   // names it in the output and in messages
  std::shared_ptr<const Scene> scene;   // null when `error` is set
  std::vector<IntersectionSpec> intersections;
  std::string error;
};

/// Unit `u` of a batch: intersection `intersection` of job `job`.
struct BatchUnit {
  std::size_t job = 0;
  std::size_t intersection = 0;
};

struct Batch {
  std::vector<BatchJob> jobs;
  std::vector<BatchUnit> units;  // every intersection of every usable job, in input order
};

/// The units of `jobs`, in input order.
std::vector<BatchUnit> batch_units(const std::vector<BatchJob>& jobs);

/// Every pair {a, b} of the scene's surfaces (surface_names order, a before b) as an
/// intersection named "a/b" with `options`, its pair kind chosen as for a scene entry without
/// "as" (pipeline/scene.hpp choose_pair_kind).
std::vector<IntersectionSpec> all_surface_pairs(const Scene& scene, const TraceJobOptions& options);

/// What one unit gave: its run, or the message of the error that stopped it.
struct BatchOutcome {
  std::optional<IntersectionRun> run;
  std::string error;
  double seconds = 0;      // wall time of the unit (for load-balance figures; not in the output)
  double cpu_seconds = 0;  // CPU time of the thread that ran it (the cost on a loaded machine)
};

/// Runs units of `batch` on `threads` threads of the shared pool (0: thread_count()) until
/// `next()` returns a number >= batch.units.size(); `next` hands out unit numbers (an atomic
/// counter in one process, a counter on MPI rank 0 across processes) and is called from
/// several threads at once. Each finished unit goes to done(u, outcome), also from several
/// threads. An error of one unit (InputError, or any std::exception) is its outcome; the
/// others go on.
void run_batch_units(const Batch& batch, unsigned threads, const std::function<std::size_t()>& next,
                     const std::function<void(std::size_t, BatchOutcome&&)>& done);

}  // namespace ssimarch
