#pragma once
// The work of `probeproxy bench`: for every probe of every scene, build every candidate proxy
// once (the proxy build's candidates: infinite, cheap_k with its fitted k, spheres, boxes, the
// hull and every convex_k of the simplification), take their mirror_floor error from that
// build, and time each candidate's lookup on the probe's mirror_floor rays.

#include "geometry/probe_proxies/build_probe_proxy.h"
#include "plugin/jobs/bench/bench_result.h"
#include "plugin/jobs/bench/lookup_timing.h"

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy::jobs {

struct BenchOptions {
  ProxyBuildOptions proxy;  // regenerate is forced on: authored proxies are measured beside
  TimingOptions timing;
  bool countInstructions = true;  // callgrind per distinct method and plane count (valgrind)
  // When set, every mirror view rebuilt with the infinite, the authored and the kept proxy is
  // written there, per scene: `<view>_<candidate>_heatmap.png`, `_miss.png` and `.exr`.
  std::filesystem::path imagesFolder;
};

// Rows in scene, probe, candidate order. Every scene is read and checked before any work
// (bad input throws InputError). `progress` gets one line per stage.
std::vector<BenchResult> benchScenes(const std::vector<std::string>& sceneFiles,
                                     const BenchOptions& options,
                                     const std::function<void(std::string_view)>& progress = {});

}  // namespace probeproxy::jobs
