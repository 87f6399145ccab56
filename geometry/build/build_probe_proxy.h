#pragma once
// The proxy pipeline for one probe: look at the level from the capture point, fit every kind
// of candidate to what it sees, measure each against the real level, keep the simplest one
// that is accurate enough ("model no more than the scene needs").

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"
#include "geometry/build/proxy_build_options.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/raycast/level_ray_caster.h"

#include <optional>

namespace probeproxy {

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
