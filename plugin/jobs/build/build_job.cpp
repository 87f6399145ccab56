#include "plugin/jobs/build/build_job.h"

#include "core/io/output_folder.h"
#include "geometry/export/runtime_export.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/level_ray_caster.h"
#include "plugin/jobs/thread_limit.h"

namespace probeproxy::jobs {

void BuildJobOptions::check() const {
  proxy.check();
  if (!outFolder.empty()) checkOutputFolder(outFolder);
}

BuildJobResult runBuildJob(const BuildJobOptions& o, const Progress& progress) {
  o.check();
  const ThreadLimit threads(o.threads);
  BuildJobResult result;
  result.scene = readSceneInput(o.input);
  const LevelMesh level = loadSceneLevel(result.scene, o.input);
  const LevelRayCaster rayCaster(level);
  result.builds = buildSceneProxies(result.scene, rayCaster, o.proxy, progress);
  if (!o.outFolder.empty()) {
    writeRuntimeExport(result.scene, result.builds, o.outFolder);
    result.proxiesJson = o.outFolder / "proxies.json";
  }
  return result;
}

}  // namespace probeproxy::jobs
