#include "ssimarch/pipeline/batch_job.hpp"

#include <chrono>
#include <ctime>
#include <exception>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/thread_pool.hpp"

namespace ssimarch {

std::vector<BatchUnit> batch_units(const std::vector<BatchJob>& jobs) {
  std::vector<BatchUnit> units;
  for (std::size_t j = 0; j < jobs.size(); ++j)
    if (jobs[j].error.empty())
      for (std::size_t i = 0; i < jobs[j].intersections.size(); ++i) units.push_back({j, i});
  return units;
}

std::vector<IntersectionSpec> all_surface_pairs(const Scene& scene, const TraceJobOptions& options) {
  std::vector<IntersectionSpec> pairs;
  const std::vector<std::string>& names = scene.surface_names;
  for (std::size_t a = 0; a < names.size(); ++a)
    for (std::size_t b = a + 1; b < names.size(); ++b) {
      IntersectionSpec spec;
      spec.name = names[a] + "/" + names[b];
      spec.surfaces = {names[a], names[b]};
      spec.kind = choose_pair_kind(scene.surface(names[a]), scene.surface(names[b]), std::nullopt,
                                   scene.source + ": " + spec.name, &spec.swapped);
      spec.options = options;
      pairs.push_back(std::move(spec));
    }
  return pairs;
}

namespace {

// CPU time of the calling thread (POSIX CLOCK_THREAD_CPUTIME_ID): a unit's cost even when other
// processes share the cores.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

BatchOutcome run_unit(const Batch& batch, const BatchUnit& unit) {
  const BatchJob& job = batch.jobs[unit.job];
  BatchOutcome outcome;
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = thread_cpu_seconds();
  // A pair's failure is its result (issue 17 item 3: the rest go on). A logic_error is a bug of
  // ours, reported the same way but named so.
  try {
    outcome.run.emplace(run_intersection(*job.scene, job.intersections[unit.intersection]));
  } catch (const InputError& e) {
    outcome.error = e.what();
  } catch (const std::logic_error& e) {
    outcome.error = std::string("internal error: ") + e.what();
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  outcome.cpu_seconds = thread_cpu_seconds() - c0;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return outcome;
}

}  // namespace

void run_batch_units(const Batch& batch, unsigned threads, const std::function<std::size_t()>& next,
                     const std::function<void(std::size_t, BatchOutcome&&)>& done) {
  // One loop per thread, each taking the next unit when it is free (self-scheduling): pair costs
  // differ by orders of magnitude, so no static split balances them.
  const unsigned loops = threads == 0 ? thread_count() : threads;
  parallel_for(loops, [&](std::size_t) {
    for (std::size_t u; (u = next()) < batch.units.size();) done(u, run_unit(batch, batch.units[u]));
  });
}

}  // namespace ssimarch
