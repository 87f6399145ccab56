#include "geometry/build/build_scene_proxies.h"

#include "geometry/build/authored_proxy_shape.h"

#include <tbb/parallel_for.h>

#include <mutex>

namespace probeproxy {

std::vector<ProbeProxyBuild> buildSceneProxies(
    const Scene& scene, const LevelRayCaster& level, const ProxyBuildOptions& options,
    const std::function<void(std::size_t, std::size_t)>& onProbeDone) {
  // Authored meshes are read first, on this thread: a bad one is reported before any work.
  std::vector<std::optional<ProxyShape>> authored;
  for (const Probe& probe : scene.probes) authored.push_back(authoredProxyShape(probe.proxy, scene));

  std::vector<ProbeProxyBuild> builds(scene.probes.size());
  std::mutex progress;
  std::size_t done = 0;
  tbb::parallel_for(std::size_t{0}, scene.probes.size(), [&](std::size_t i) {
    builds[i] = buildProbeProxy(level, scene.probes[i], authored[i], options);
    if (onProbeDone) {
      const std::lock_guard<std::mutex> lock(progress);
      onProbeDone(++done, scene.probes.size());
    }
  });
  return builds;
}

}  // namespace probeproxy
