#include "core/errors/input_error.h"
#include "geometry/level/load_level.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/scene/scene_file.h"
#include "plugin/cli/verb.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct BuildOptions {
  std::string scene;
  std::string out;
  bool json = false;
  double toleranceDeg = 1.0;
  int maxPlanes = 32;
  int faceSize = 128;
};

int runBuild(const BuildOptions& o) {
  // Everything the proxy fit will need is read and checked first, so bad input is reported
  // before any work and before anything is written.
  const Scene scene = readSceneFile(o.scene);
  const LevelMesh level = loadLevel(scene);
  const LevelRayCaster rayCaster(level);
  for (const Probe& probe : scene.probes) captureDepthCube(rayCaster, probe.captureMeters, o.faceSize);
  std::cerr << "probeproxy build: read " << scene.probes.size() << " probes and "
            << level.triangles.size() << " triangles from " << o.scene << "\n"
            << "probeproxy build: not available yet: proxy generation lands with issue 3\n";
  return kExitBadInput;
}

}  // namespace

Verb addBuildVerb(CLI::App& app) {
  auto o = std::make_shared<BuildOptions>();
  CLI::App* build = app.add_subcommand(
      "build", "Build each probe's convex proxy from the level and measure its error");
  build->add_option("scene", o->scene, "scene file (*.scene.json)")->required();
  build->add_option("--out", o->out, "output folder for proxies.json and proxies.glb")->required();
  build->add_flag("--json", o->json, "print the build report as JSON on stdout");
  build->add_option("--tolerance-deg", o->toleranceDeg,
                    "keep the simplest proxy whose p95 angular error is under this")
      ->capture_default_str()->check(CLI::PositiveNumber);
  build->add_option("--max-planes", o->maxPlanes, "never use more planes than this")
      ->capture_default_str()->check(CLI::Range(4, 256));
  build->add_option("--face-size", o->faceSize, "depth cube face size in texels")
      ->capture_default_str()->check(CLI::Range(8, 2048));
  return {build, [o] { return runBuild(*o); }};
}

}  // namespace probeproxy::cli
