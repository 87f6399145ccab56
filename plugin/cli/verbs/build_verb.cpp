#include "core/errors/input_error.h"
#include "geometry/build/build_scene_proxies.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/load_level.h"
#include "geometry/scene/scene_file.h"
#include "plugin/cli/reports/build_report.h"
#include "plugin/cli/verb.h"

#include <tbb/global_control.h>

#include <unistd.h>
#include <iostream>
#include <memory>
#include <optional>

namespace probeproxy::cli {

namespace {

struct BuildOptions {
  std::string scene;
  std::string out;
  bool json = false;
  bool report = true;  // `export` writes the same files without the candidate table
  int threads = 0;     // 0: all cores
  ProxyBuildOptions proxy;
};

int runBuild(const BuildOptions& o) {
  std::optional<tbb::global_control> threadLimit;
  if (o.threads > 0) threadLimit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);

  // Everything is read and checked before any work, and nothing is written until the end.
  const Scene scene = readSceneFile(o.scene);
  const LevelMesh level = loadLevel(scene);
  const LevelRayCaster rayCaster(level);

  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  const std::vector<ProbeProxyBuild> builds =
      buildSceneProxies(scene, rayCaster, o.proxy, [&](std::size_t done, std::size_t total) {
        if (terminal)
          std::cerr << "\rprobeproxy build: " << done << "/" << total << " probes" << std::flush;
      });
  if (terminal) std::cerr << "\n";

  writeRuntimeExport(scene, builds, o.out);
  for (const ProbeProxyBuild& b : builds) {
    for (const std::string& finding : b.findings)
      std::cerr << "probe " << b.probe << ": " << finding << "\n";
  }
  if (o.json) {
    std::cout << buildReportJson(builds);
  } else {
    if (o.report) printBuildTable(std::cout, builds);
    std::cout << "wrote " << (std::filesystem::path(o.out) / "proxies.json").string()
              << " and proxies.glb\n";
  }
  return 0;
}

void addProxyOptions(CLI::App* verb, BuildOptions& o) {
  verb->add_option("scene", o.scene, "scene file (*.scene.json)")->required();
  verb->add_option("--out", o.out, "output folder for proxies.json and proxies.glb")->required();
  verb->add_flag("--json", o.json, "print the build report as JSON on stdout");
  verb->add_option("--tolerance-deg", o.proxy.toleranceDeg,
                   "keep the fewest planes whose mirror_floor p95 angular error is under this")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  verb->add_option("--max-planes", o.proxy.maxPlanes, "never keep more planes than this")
      ->capture_default_str()
      ->check(CLI::Range(4, 256));
  verb->add_option("--max-miss-rate", o.proxy.maxMissRate,
                   "share of visible samples a kept proxy may miss")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  verb->add_option("--face-size", o.proxy.depthFaceSize, "depth cube face size in texels")
      ->capture_default_str()
      ->check(CLI::Range(8, 2048));
  verb->add_option("--samples", o.proxy.samples.targetSamples, "reflection samples per set")
      ->capture_default_str()
      ->check(CLI::Range(64, 1000000));
  verb->add_flag("--regenerate", o.proxy.regenerate,
                 "generate a proxy also where the scene authors one (which is measured beside)");
  verb->add_option("--threads", o.threads, "worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

}  // namespace

Verb addBuildVerb(CLI::App& app) {
  auto o = std::make_shared<BuildOptions>();
  CLI::App* build = app.add_subcommand(
      "build", "Build each probe's convex proxy from the level, measure every candidate, export");
  addProxyOptions(build, *o);
  return {build, [o] { return runBuild(*o); }};
}

Verb addExportVerb(CLI::App& app) {
  auto o = std::make_shared<BuildOptions>();
  o->report = false;
  CLI::App* exportVerb = app.add_subcommand(
      "export",
      "Write proxies.json and proxies.glb for the game runtime: authored proxies as "
      "they are, `auto` ones generated");
  addProxyOptions(exportVerb, *o);
  return {exportVerb, [o] { return runBuild(*o); }};
}

}  // namespace probeproxy::cli
