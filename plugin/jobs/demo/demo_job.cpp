#include "plugin/jobs/demo/demo_job.h"

#include "core/blend/weight_picture_legend.h"
#include "core/cube/write_depth_cube.h"
#include "core/errors/input_error.h"
#include "core/errors/option_checks.h"
#include "core/image/write_png.h"
#include "core/io/atomic_write.h"
#include "core/io/output_folder.h"
#include "geometry/builtin/box_room.h"
#include "geometry/builtin/builtin_corridor.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/load_level.h"
#include "geometry/level/write_level_mesh.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/scene/scene_file.h"
#include "geometry/validate/validate_scene.h"
#include "plugin/jobs/bench/bench_report.h"
#include "plugin/jobs/bench/bench_scenes.h"
#include "plugin/jobs/build/build_report.h"
#include "plugin/jobs/validate/validate_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <memory>
#include <ostream>

namespace probeproxy::jobs {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The built-in corridor is a box, so every depth texel has an exact answer to compare with.
double largestDepthError(const DepthCube& cube, glm::dvec3 lo, glm::dvec3 hi) {
  double worst = 0.0;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < cube.faceSize; ++row) {
      for (int col = 0; col < cube.faceSize; ++col) {
        const glm::dvec3 d(texelDirection(CubeFace(f), col, row, cube.faceSize));
        const double exact = boxRoomDistance(lo, hi, cube.captureMeters, d);
        worst = std::max(worst, std::abs(cube.at(CubeFace(f), col, row) - exact));
      }
    }
  }
  return worst;
}

// The charts are drawn by scripts/bench_charts.py with Debian's python3-matplotlib; without
// them the demo still finishes and says how to draw them.
void drawCharts(const std::filesystem::path& benchJson, const std::filesystem::path& folder,
                std::ostream& narrative) {
  const std::filesystem::path script =
      std::filesystem::path(PROBEPROXY_SOURCE_DIR) / "scripts" / "bench_charts.py";
  std::string command = "/usr/bin/python3 '";
  command += script.string();
  command += "' '";
  command += benchJson.string();
  command += "' '";
  command += folder.string();
  command += "' >/dev/null";
  if (std::filesystem::exists(script) && std::system(command.c_str()) == 0) {
    narrative << "drew the speed-against-accuracy charts: " << folder.string() << "\n";
  } else {
    narrative << "charts not drawn (needs " << script.string()
              << " and python3-matplotlib): " << command << "\n";
  }
}

}  // namespace

void DemoJobOptions::check() const {
  if (outFolder.empty()) throw InputError("--out", "the demo needs an output folder");
  requireInRange("face_size", faceSize, 8, 2048);
  checkOutputFolder(outFolder);
}

void runDemoJob(const DemoJobOptions& o, std::ostream& narrative) {
  o.check();
  const std::filesystem::path& out = o.outFolder;
  const auto start = std::chrono::steady_clock::now();

  // 1. Put the built-in level on disk as a user would have it, then read it back through the
  //    same scene and mesh readers every other verb uses.
  const BuiltinLevel builtin = builtinCorridor();
  writeLevelMeshFile(builtin.level, out / builtin.meshFileName, UpAxis::Z);
  const std::filesystem::path sceneFile = out / "corridor.scene.json";
  writeSceneFile(builtin.scene, sceneFile);
  narrative << "wrote the built-in level (the seed's corridor, 18 x 3 x 3 m, 3 probes): "
            << sceneFile.string() << "\n";

  const Scene scene = readSceneFile(sceneFile);
  const LevelMesh level = loadLevel(scene);
  const LevelMeshStats stats = measureLevelMesh(level);
  narrative << "loaded " << stats.vertices << " vertices, " << stats.triangles << " triangles ("
            << stats.degenerateTriangles << " degenerate) in " << level.parts.size()
            << " mesh(es)\n";

  // 2. Ray-cast each probe's depth cube with Embree and check it against the exact corridor.
  const LevelRayCaster rayCaster(level);
  const glm::dvec3 lo(stats.boundsMinMeters), hi(stats.boundsMaxMeters);
  for (const Probe& probe : scene.probes) {
    const auto castStart = std::chrono::steady_clock::now();
    const DepthCube cube = captureDepthCube(rayCaster, probe.captureMeters, o.faceSize);
    const double castSeconds = secondsSince(castStart);
    const std::string pattern = (out / "depth" / (probe.name + "_depth_{face}.exr")).string();
    writeDepthCube(cube, pattern);
    narrative << std::fixed << std::setprecision(2) << "probe " << probe.name << ": depth cube "
              << o.faceSize << " px/face, " << 6 * o.faceSize * o.faceSize << " rays in "
              << castSeconds * 1e3 << " ms, largest error against the exact corridor "
              << std::scientific << std::setprecision(1) << largestDepthError(cube, lo, hi)
              << " m -> " << cubeFacePath(pattern, CubeFace::px).parent_path().string() << "\n"
              << std::defaultfloat;
  }

  // 3. Build every probe's proxy from the level (the authored artist boxes are measured
  //    beside), keep the simplest accurate one, and export it for the runtime.
  ProxyBuildOptions options;
  options.regenerate = true;
  const std::vector<ProbeProxyBuild> builds = buildSceneProxies(scene, rayCaster, options);
  printBuildTable(narrative, builds);
  writeRuntimeExport(scene, builds, out / "export");
  narrative << "exported the proxies for the runtime: "
            << (out / "export" / "proxies.json").string() << " and proxies.glb\n";

  // 4. Validate the authored volumes against the level, as a pipeline would before shipping.
  const std::vector<ValidationFinding> findings = validateScene(scene, rayCaster);
  printFindings(narrative, sceneFile.string(), findings);

  // 5. Where each probe contributes: the top-down blend-weight picture at capture height.
  const Rgb8Canvas picture = sceneWeightPicture(scene, scene.probes.front().captureMeters.z, {});
  writePng(out / "blend_weights.png", picture.width, picture.height, picture.rgb8);
  narrative << "wrote the blend weights seen from above: " << (out / "blend_weights.png").string()
            << "\n";

  // 6. Speed against accuracy of every method on this level, and its charts.
  if (o.bench) {
    BenchOptions bench;
    bench.timing.repetitions = 3;
    const std::vector<BenchResult> results = benchScenes({sceneFile.string()}, bench);
    printBenchTable(narrative, results);
    const std::filesystem::path benchJson = out / "bench" / "bench.json";
    std::filesystem::create_directories(benchJson.parent_path());
    writeFileAtomically(benchJson, benchReportJson(results));
    drawCharts(benchJson, out / "charts", narrative);
  }
  narrative << "done in " << std::setprecision(3) << secondsSince(start) << " s\n";
}

}  // namespace probeproxy::jobs
