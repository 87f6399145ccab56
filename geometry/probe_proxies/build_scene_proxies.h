#pragma once
// Every probe of a scene, built in parallel (TBB, one task per probe). Probes are independent
// and each one's work is deterministic, so the result is the same for any thread count.

#include "core/proxy/proxy_candidate.h"
#include "core/scene/scene.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/raycast/level_ray_caster.h"

#include <functional>
#include <vector>

namespace probeproxy {

// The level surface nearest `point`, in any direction: a point lying in a wall's own plane is
// on that wall, though every ray along the plane misses it.
SurfacePoint nearestSurface(const LevelRayCaster& level, glm::dvec3 point);

// A capture point closer than this to a level surface is refused (InputError naming the probe,
// the distance and the triangle): its cubemap would see the level from behind the surface.
inline constexpr double kMinCaptureClearanceMeters = 0.01;

// Throws InputError for the first probe whose capture point is outside its influence volume
// (it has no reflections to fit to) or within kMinCaptureClearanceMeters of a surface. Run by
// buildSceneProxies first; callers that read several scenes before any work run it too.
void checkCapturePoints(const Scene& scene, const LevelRayCaster& level);

// `onProbeDone(done, total)` is called as probes finish (from worker threads, serialized).
std::vector<ProbeProxyBuild> buildSceneProxies(
    const Scene& scene, const LevelRayCaster& level, const ProxyBuildOptions& options,
    const std::function<void(std::size_t, std::size_t)>& onProbeDone = {});

}  // namespace probeproxy
