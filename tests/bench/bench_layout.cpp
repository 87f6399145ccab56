// Layout cost (plugin/jobs/layout: `probeproxy layout`, without writing files) on one level:
// the whole job (floor, candidates with their coarse proxies, selection, influence boxes, final
// proxies, the survey of the result), and in the same process the grid baseline at 4 m (probes
// on a grid, aabb proxies, the same survey) as the reference the ratio is taken against.
// The target: the largest corpus map (warfare) under 60 s on 2 cores, median of 3:
//   bench_layout --scene build/corpus/scenes/warfare/warfare.scene.json
//                --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// Counters: probes, candidates, candidate_ms (one candidate's median cost), p95_deg.

#include "plugin/jobs/layout/layout_job.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

void runLayout(benchmark::State& state, const std::string& scene, LayoutBaseline baseline) {
  jobs::LayoutJobOptions options;
  options.levelOrScene = scene;
  options.layout.baseline = baseline;
  if (baseline == LayoutBaseline::Grid) options.layout.spacingMeters = 4.0;
  jobs::LayoutJobResult result;
  for (auto _ : state) {
    result = jobs::runLayoutJob(options);
    benchmark::DoNotOptimize(result.scene.probes.data());
  }
  state.counters["probes"] = static_cast<double>(result.scene.probes.size());
  state.counters["candidates"] = static_cast<double>(result.layout.candidates);
  if (result.layout.candidates > 0)
    state.counters["candidate_ms"] = result.layout.candidateMedianMs;
  state.counters["p95_deg"] = result.survey.figures.p95Deg;
}

}  // namespace
}  // namespace probeproxy

int main(int argc, char** argv) {
  using namespace probeproxy;
  std::string scene;
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc) {
      scene = argv[++i];
    } else {
      rest.push_back(argv[i]);
    }
  }
  if (scene.empty()) {
    std::cerr << "bench_layout: --scene SCENE_OR_LEVEL is required\n";
    return 2;
  }
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());
  const std::string name = std::filesystem::path(scene).stem().stem().string();
  benchmark::RegisterBenchmark(
      ("layout/" + name).c_str(),
      [scene](benchmark::State& s) { runLayout(s, scene, LayoutBaseline::None); })
      ->Unit(benchmark::kSecond)
      ->UseRealTime()
      ->Iterations(1);
  benchmark::RegisterBenchmark(
      ("grid_4m_baseline/" + name).c_str(),
      [scene](benchmark::State& s) { runLayout(s, scene, LayoutBaseline::Grid); })
      ->Unit(benchmark::kSecond)
      ->UseRealTime()
      ->Iterations(1);
  try {
    benchmark::RunSpecifiedBenchmarks();
  } catch (const std::exception& e) {
    std::cerr << "bench_layout: " << e.what() << "\n";
    return 2;
  }
  benchmark::Shutdown();
  return 0;
}
