#pragma once
// The proxy pipeline for one probe: look at the level from the capture point, fit every kind
// of candidate to what it sees, measure each against the real level, keep the simplest one
// that is accurate enough ("model no more than the scene needs").

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/raycast/level_ray_caster.h"

#include <optional>

namespace probeproxy {

struct ProxyBuildOptions {
  double toleranceDeg = 0.25;  // keep the fewest planes whose mirror_floor p95 is under this
  int maxPlanes = 64;          // never keep more planes than this
  double maxMissRate = 0.001;  // a kept proxy may miss at most this share of visible samples
  int depthFaceSize = 128;     // depth cube the candidates are fitted to
  bool regenerate = false;     // build a proxy even where the scene file has an authored one
  ReflectionSampleOptions samples;
};

// Candidates in a fixed order: `authored` (the scene file's proxy, if it has one), infinite,
// cheap_k, sphere (fitted around the capture point), min_sphere (smallest enclosing), aabb,
// obb, hull, then convex_k from the hull's plane count down. The kept one is chosen by
// selectProxy: the authored one unless options.regenerate.
ProbeProxyBuild buildProbeProxy(const LevelRayCaster& level, const Probe& probe,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& options);

// Index of the candidate to keep (see ProxyBuildOptions), given candidates built as above.
std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates,
                        const ProxyBuildOptions& options);

}  // namespace probeproxy
