// Ray-casting throughput against the level: the depth cube of every probe of a scene, cast
// batched over all cores (what probeproxy does) and one ray at a time on one thread (the
// baseline, same process, same rays). Report medians:
//   bench_raycast --scene build/scenes/hall_pillars/hall_pillars.scene.json --face-size 128
//     --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Without --scene it runs on the built-in corridor.

#include "geometry/builtin/builtin_corridor.h"
#include "geometry/level/load_level.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/scene/scene_file.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <iostream>
#include <map>

namespace probeproxy {
namespace {

struct Workload {
  std::string name;
  std::unique_ptr<LevelRayCaster> caster;
  std::vector<Ray> rays;  // every probe's depth cube rays, one after the other
};

Workload loadWorkload(const std::string& sceneFile, int faceSize) {
  Workload w;
  Scene scene;
  LevelMesh level;
  if (sceneFile.empty()) {
    BuiltinLevel builtin = builtinCorridor();
    scene = std::move(builtin.scene);
    level = std::move(builtin.level);
    w.name = "builtin_corridor";
  } else {
    scene = readSceneFile(sceneFile);
    level = loadLevel(scene);
    w.name = std::filesystem::path(sceneFile).stem().stem().string();
  }
  w.caster = std::make_unique<LevelRayCaster>(level);
  for (const Probe& probe : scene.probes) {
    const std::vector<Ray> rays = depthCubeRays(probe.captureMeters, faceSize);
    w.rays.insert(w.rays.end(), rays.begin(), rays.end());
  }
  return w;
}

// Prints the usual table and remembers each benchmark's median, so the run can end with the
// batched path's speed-up over the one-by-one baseline measured in this same process.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
        medianSeconds[run.run_name.function_name] = run.GetAdjustedRealTime();
      } else if (run.run_type == Run::RT_Iteration &&
                 !medianSeconds.count(run.run_name.function_name)) {
        medianSeconds[run.run_name.function_name] = run.GetAdjustedRealTime();  // one repetition
      }
    }
  }
  std::map<std::string, double> medianSeconds;
};

void setRaysPerSecond(benchmark::State& state, std::size_t rays) {
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

}  // namespace
}  // namespace probeproxy

int main(int argc, char** argv) {
  using namespace probeproxy;
  std::string sceneFile;
  int faceSize = 128;
  // Our own flags first; the rest belong to Google Benchmark.
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc) {
      sceneFile = argv[++i];
    } else if (std::strcmp(argv[i], "--face-size") == 0 && i + 1 < argc) {
      faceSize = std::atoi(argv[++i]);
    } else {
      rest.push_back(argv[i]);
    }
  }
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());

  static Workload w;
  try {
    w = loadWorkload(sceneFile, faceSize);
  } catch (const std::exception& e) {
    std::cerr << "bench_raycast: " << e.what() << "\n";
    return 2;
  }
  const std::string suffix = "/" + w.name + "/" + std::to_string(faceSize) + "px";

  benchmark::RegisterBenchmark(("depth_cubes_one_by_one_1thread" + suffix).c_str(),
                               [](benchmark::State& state) {
                                 std::vector<RayHit> hits(w.rays.size());
                                 for (auto _ : state) {
                                   w.caster->firstHitsOneByOne(w.rays, hits);
                                   benchmark::DoNotOptimize(hits.data());
                                 }
                                 setRaysPerSecond(state, w.rays.size());
                               })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark(("depth_cubes_batched_all_cores" + suffix).c_str(),
                               [](benchmark::State& state) {
                                 std::vector<RayHit> hits(w.rays.size());
                                 for (auto _ : state) {
                                   w.caster->firstHits(w.rays, hits, /*coherent=*/true);
                                   benchmark::DoNotOptimize(hits.data());
                                 }
                                 setRaysPerSecond(state, w.rays.size());
                               })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  const double baseline = reporter.medianSeconds["depth_cubes_one_by_one_1thread" + suffix];
  const double batched = reporter.medianSeconds["depth_cubes_batched_all_cores" + suffix];
  if (baseline > 0 && batched > 0) {
    std::cout << "rays per depth-cube set: " << w.rays.size() << "; median rays/s: one by one "
              << w.rays.size() / (baseline * 1e-3) / 1e6 << " M, batched "
              << w.rays.size() / (batched * 1e-3) / 1e6
              << " M; batched / one-by-one speed-up: " << baseline / batched << "x\n";
  }
  return 0;
}
