// Proxy build time per probe: the whole pipeline of geometry/probe_proxies/build_probe_proxy.h (depth
// cube, reflection samples, hull, fits, simplification, evaluation) for each probe of a scene,
// one probe at a time, with the share of each stage. Report medians:
//   bench_build_proxy --scene build/scenes/hall_pillars/hall_pillars.scene.json --face-size 128
//     --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Without --scene it runs on the built-in corridor.

#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/builtin/builtin_corridor.h"
#include "geometry/level/load_level.h"
#include "geometry/scene/scene_file.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <iostream>

namespace probeproxy {
namespace {

struct Workload {
  std::string name;
  Scene scene;
  std::unique_ptr<LevelRayCaster> caster;
  ProxyBuildOptions options;
};

Workload w;

void buildEveryProbe(benchmark::State& state) {
  double depth = 0, sampling = 0, hull = 0, simplify = 0, fits = 0, evaluation = 0, total = 0;
  for (auto _ : state) {
    for (const Probe& probe : w.scene.probes) {
      const ProbeProxyBuild b = buildProbeProxy(*w.caster, probe, std::nullopt, w.options);
      benchmark::DoNotOptimize(b.kept);
      depth += b.depthMs, sampling += b.samplingMs, hull += b.hullMs, simplify += b.simplifyMs;
      fits += b.fitMs, evaluation += b.evaluateMs, total += b.buildMs;
    }
  }
  const double probes = static_cast<double>(state.iterations() * w.scene.probes.size());
  state.counters["ms_per_probe"] = total / probes;
  for (const auto& [name, ms] : {std::pair{"depth_share", depth},
                                 {"sampling_share", sampling},
                                 {"hull_share", hull},
                                 {"simplify_share", simplify},
                                 {"fits_share", fits},
                                 {"evaluation_share", evaluation}}) {
    state.counters[name] = ms / total;
  }
}

}  // namespace
}  // namespace probeproxy

int main(int argc, char** argv) {
  using namespace probeproxy;
  std::string sceneFile;
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc) {
      sceneFile = argv[++i];
    } else if (std::strcmp(argv[i], "--face-size") == 0 && i + 1 < argc) {
      w.options.depthFaceSize = std::atoi(argv[++i]);
    } else {
      rest.push_back(argv[i]);
    }
  }
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());
  try {
    if (sceneFile.empty()) {
      BuiltinLevel builtin = builtinCorridor();
      w.scene = std::move(builtin.scene);
      w.caster = std::make_unique<LevelRayCaster>(builtin.level);
      w.name = "builtin_corridor";
    } else {
      w.scene = readSceneFile(sceneFile);
      w.caster = std::make_unique<LevelRayCaster>(loadLevel(w.scene));
      w.name = std::filesystem::path(sceneFile).stem().stem().string();
    }
  } catch (const std::exception& e) {
    std::cerr << "bench_build_proxy: " << e.what() << "\n";
    return 2;
  }
  benchmark::RegisterBenchmark(
      ("build_proxy_every_probe/" + w.name + "/" + std::to_string(w.options.depthFaceSize) + "px")
          .c_str(),
      buildEveryProbe)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
