#include "geometry/probe_proxies/build_scene_proxies.h"

#include "geometry/probe_proxies/authored_proxy_shape.h"

#include "core/errors/input_error.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <limits>
#include <mutex>
#include <sstream>

namespace probeproxy {

SurfacePoint nearestSurface(const LevelRayCaster& level, glm::dvec3 point) {
  const SurfacePoint nearest =
      level.nearestTriangle(point, std::numeric_limits<double>::infinity());
  return {nearest.distanceMeters, nearest.triangle};
}

void checkCapturePoints(const Scene& scene, const LevelRayCaster& level) {
  // A probe outside its own influence volume has no reflections to fit a proxy to (the samples
  // live in the volume): bad input, said before any work. `validate` reports it as a finding.
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const Probe& probe = scene.probes[i];
    if (!insideInfluence(probe.influence, probe.captureMeters)) {
      std::ostringstream problem;
      problem << "$.probes[" << i << "]: probe '" << probe.name << "' captures at ("
              << probe.captureMeters.x << ", " << probe.captureMeters.y << ", "
              << probe.captureMeters.z << ") m, outside its influence volume; move the capture "
              << "point into the volume or the volume over it";
      throw InputError(scene.file, problem.str());
    }
  }

  // A capture point on a surface sees half the level from behind it: no proxy can contain it.
  // Said before any work, with the nearest surface and how far to move.
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const Probe& probe = scene.probes[i];
    const SurfacePoint near = nearestSurface(level, probe.captureMeters);
    if (near.distanceMeters < kMinCaptureClearanceMeters) {
      std::ostringstream problem;
      problem << "$.probes[" << i << "]: probe '" << probe.name << "' captures at ("
              << probe.captureMeters.x << ", " << probe.captureMeters.y << ", "
              << probe.captureMeters.z << ") m, "
              << (near.distanceMeters > 0.0 ? near.distanceMeters : 0.0)
              << " m from a level surface (triangle " << near.triangle
              << "); move the capture point at least " << kMinCaptureClearanceMeters
              << " m off it, into the room";
      throw InputError(scene.file, problem.str());
    }
  }
}

std::vector<ProbeProxyBuild> buildSceneProxies(
    const Scene& scene, const LevelRayCaster& level, const ProxyBuildOptions& options,
    const std::function<void(std::size_t, std::size_t)>& onProbeDone) {
  options.check();
  checkCapturePoints(scene, level);

  // Authored meshes are read first, on this thread: a bad one is reported before any work.
  std::vector<std::optional<ProxyShape>> authored;
  for (const Probe& probe : scene.probes)
    authored.push_back(authoredProxyShape(probe.proxy, scene));

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
