#include "plugin/jobs/bench/lookup_timing.h"

#include <benchmark/benchmark.h>

#include <map>
#include <string>

namespace probeproxy::jobs {

namespace {

// The scratch output the lookups write to; one per job, so nothing is shared between runs.
struct Scratch {
  std::vector<float> dx, dy, dz;
  std::vector<std::uint8_t> miss;
};

void scalarLookups(benchmark::State& state, const TimingJob& job, Scratch* out) {
  const LookupRays& r = *job.rays;
  for (auto _ : state) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const seed::Lookup l =
          lookupScalar(*job.proxy, {r.x[i], r.y[i], r.z[i]}, {r.dirX[i], r.dirY[i], r.dirZ[i]});
      out->dx[i] = l.direction.x, out->dy[i] = l.direction.y, out->dz[i] = l.direction.z;
      out->miss[i] = l.miss;
    }
    benchmark::DoNotOptimize(out->dx.data());
    benchmark::ClobberMemory();
  }
}

void batchedLookups(benchmark::State& state, const TimingJob& job, Scratch* out) {
  const LookupRays& r = *job.rays;
  const RaysSoA rays{r.x, r.y, r.z, r.dirX, r.dirY, r.dirZ};
  const LookupsSoA lookups{out->dx, out->dy, out->dz, out->miss};
  for (auto _ : state) {
    lookupBatch(*job.proxy, rays, lookups);
    benchmark::DoNotOptimize(out->dx.data());
    benchmark::ClobberMemory();
  }
}

void calls(benchmark::State& state, const CallJob& job) {
  for (auto _ : state) job.call();
}

// Keeps each benchmark's median CPU time per iteration (or its only run when there is one
// repetition) and prints nothing: the bench verb has its own table.
class MedianReporter : public benchmark::BenchmarkReporter {
 public:
  explicit MedianReporter(std::function<void()> onBenchmark)
      : onBenchmark_(std::move(onBenchmark)) {}
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      const std::string name = run.run_name.function_name;
      if (run.error_occurred) continue;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
        seconds[name] = run.GetAdjustedCPUTime();
      } else if (run.run_type == Run::RT_Iteration && !seconds.count(name)) {
        seconds[name] = run.GetAdjustedCPUTime();
      }
    }
    if (onBenchmark_) onBenchmark_();
  }
  std::map<std::string, double> seconds;  // in the benchmark's time unit (ns) per iteration

 private:
  std::function<void()> onBenchmark_;
};

// Google Benchmark takes its settings as command-line flags; these are the CLI's, not the
// user's argv, so `probeproxy bench` options never leak into the library's parser.
void initializeBenchmarkLibrary(const TimingOptions& o) {
  std::string minTime = "--benchmark_min_time=" + std::to_string(o.minTimeSeconds);
  std::string reps = "--benchmark_repetitions=" + std::to_string(o.repetitions);
  std::string aggregates = "--benchmark_report_aggregates_only=true";
  std::string program = "probeproxy";
  char* argv[] = {program.data(), minTime.data(), reps.data(), aggregates.data(), nullptr};
  int argc = 4;
  benchmark::Initialize(&argc, argv);
}

}  // namespace

void keepResult(const void* result) { benchmark::DoNotOptimize(result); }

Timings timeBenchmarks(const std::vector<TimingJob>& jobs, const std::vector<CallJob>& callJobs,
                       const TimingOptions& options,
                       const std::function<void(std::size_t, std::size_t)>& onDone) {
  initializeBenchmarkLibrary(options);
  std::vector<Scratch> scratch(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const std::size_t n = jobs[j].rays->size();
    scratch[j] = {std::vector<float>(n), std::vector<float>(n), std::vector<float>(n),
                  std::vector<std::uint8_t>(n)};
    const std::string id = std::to_string(j);
    // Scalar then batched for each proxy: the pair runs back to back, under the same load.
    benchmark::RegisterBenchmark(("scalar/" + id).c_str(), scalarLookups, jobs[j], &scratch[j]);
    benchmark::RegisterBenchmark(("batched/" + id).c_str(), batchedLookups, jobs[j], &scratch[j]);
  }
  for (std::size_t c = 0; c < callJobs.size(); ++c)
    benchmark::RegisterBenchmark(("call/" + std::to_string(c)).c_str(), calls, callJobs[c]);
  std::size_t done = 0;
  const std::size_t total = 2 * jobs.size() + callJobs.size();
  MedianReporter reporter([&] {
    if (onDone) onDone(++done, total);
  });
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();

  Timings timings;
  timings.lookups.resize(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const double rays = static_cast<double>(jobs[j].rays->size());
    const std::string id = std::to_string(j);
    if (auto s = reporter.seconds.find("scalar/" + id); s != reporter.seconds.end())
      timings.lookups[j].scalarNs = s->second / rays;
    if (auto b = reporter.seconds.find("batched/" + id); b != reporter.seconds.end())
      timings.lookups[j].batchedNs = b->second / rays;
  }
  timings.nsPerItem.resize(callJobs.size());
  for (std::size_t c = 0; c < callJobs.size(); ++c) {
    if (auto t = reporter.seconds.find("call/" + std::to_string(c)); t != reporter.seconds.end())
      timings.nsPerItem[c] = t->second / callJobs[c].itemsPerCall;
  }
  return timings;
}

}  // namespace probeproxy::jobs
