#pragma once
// Every probe of a scene, built in parallel (TBB, one task per probe). Probes are independent
// and each one's work is deterministic, so the result is the same for any thread count.

#include "core/proxy/proxy_candidate.h"
#include "core/scene/scene.h"
#include "geometry/build/build_probe_proxy.h"
#include "geometry/raycast/level_ray_caster.h"

#include <functional>
#include <vector>

namespace probeproxy {

// `onProbeDone(done, total)` is called as probes finish (from worker threads, serialized).
std::vector<ProbeProxyBuild> buildSceneProxies(
    const Scene& scene, const LevelRayCaster& level, const ProxyBuildOptions& options,
    const std::function<void(std::size_t, std::size_t)>& onProbeDone = {});

}  // namespace probeproxy
