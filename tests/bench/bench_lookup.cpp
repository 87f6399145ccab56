// Cubemap lookup cost per method: the seeds' scalar shader ports (one ray per call) and the
// batched SoA kernels (4096 rays per call) on the same rays, in one process, then the batched
// speed-up per method. Report medians:
//   bench_lookup --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include "plugin/cost/lookup_workload.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

constexpr std::size_t kRays = 4096;

// The shared cost workloads (plugin/cost/lookup_workload.h): the callgrind driver counts
// instructions on the same rays.
struct Workload {
  LookupWorkload w;
  LookupOutputs out{kRays};
};

void scalarLookups(benchmark::State& state, Workload* w) {
  for (auto _ : state) {
    runScalarLookups(w->w, w->out);
    benchmark::DoNotOptimize(w->out.dx.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}

void batchedLookups(benchmark::State& state, Workload* w) {
  for (auto _ : state) {
    runBatchedLookups(w->w, w->out);
    benchmark::DoNotOptimize(w->out.dx.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}

// The console table, plus each benchmark's median CPU time (or its only run) kept for the
// speed-up summary. CPU time, not wall time: the loops run on one thread, and on a shared
// machine wall time also counts the time other processes hold the core.
class SpeedupReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const std::string name = run.run_name.function_name;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
        seconds[name] = run.GetAdjustedCPUTime();
      else if (run.run_type == Run::RT_Iteration && !seconds.count(name))
        seconds[name] = run.GetAdjustedCPUTime();
    }
  }
  std::map<std::string, double> seconds;
};

}  // namespace
}  // namespace probeproxy

int main(int argc, char** argv) {
  using namespace probeproxy;
  std::vector<Workload> ws;
  for (const std::string& name : costTableWorkloads())
    ws.push_back({makeLookupWorkload(name, kRays)});
  for (Workload& w : ws) {
    benchmark::RegisterBenchmark(("scalar/" + w.w.name).c_str(), scalarLookups, &w);
    benchmark::RegisterBenchmark(("batched/" + w.w.name).c_str(), batchedLookups, &w);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SpeedupReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  std::printf("\nns per lookup (median) and batched speed-up over scalar, %zu rays per call:\n",
              kRays);
  for (const Workload& w : ws) {
    const auto s = reporter.seconds.find("scalar/" + w.w.name);
    const auto b = reporter.seconds.find("batched/" + w.w.name);
    if (s == reporter.seconds.end() || b == reporter.seconds.end()) continue;
    // GetAdjustedCPUTime is in the benchmark's time unit (ns by default) per iteration.
    std::printf("  %-10s scalar %7.2f ns  batched %7.2f ns  speed-up %5.1fx\n", w.w.name.c_str(),
                s->second / kRays, b->second / kRays, s->second / b->second);
  }
  return 0;
}
