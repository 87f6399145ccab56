#pragma once
// The proxy pipeline for one probe: look at the level from the capture point, fit every kind
// of candidate to what it sees, measure each against the real level, keep the simplest one
// that is accurate enough ("model no more than the scene needs"). Its stages, in order, each a
// file of this folder with a test of its own:
//   1. seeLevel           probe_view.h      the depth cube, the points and walls seen
//   2. drawProbeSamples   probe_samples.h   reflection samples to fit on and to report on
//   3. fitCandidates      fit_candidates.h  authored, infinite, cheap_k, spheres, boxes, hull
//   4. simplifyHull       simplify_hull.h   convex_k for every plane count the error allows
//   5. measure            evaluate_shape.h  each candidate's error on mirror_floor
//   6. selectProxy        select_proxy.h    which one to keep; a simplification step whose
//                                           corners reach far is dropped and it runs again
//   7. finishKeptProxy    (here)            the kept convex's corners; the capture inside it

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/probe_proxies/fit_candidates.h"
#include "geometry/probe_proxies/probe_samples.h"
#include "geometry/probe_proxies/probe_view.h"
#include "geometry/probe_proxies/proxy_build_options.h"
#include "geometry/probe_proxies/select_proxy.h"
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

// The same build with stage 1 and the hull already made for the probe's capture point
// (seeLevel at options.depthFaceSize, fitViewHull): layout builds one capture point's proxy for
// several influence volumes. Its depthMs is 0; hullMs is the shared hull's.
ProbeProxyBuild buildProbeProxy(const LevelRayCaster& level, const Probe& probe,
                                const ProbeView& view, const ViewHull& hull,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& options);

// The same with stage 2's samples already drawn (drawProbeSamples for the probe, its fit set
// perhaps another region's): layout fits one probe's proxy to several regions and reports each
// on the same floor. Its samplingMs is 0.
ProbeProxyBuild buildProbeProxy(const Probe& probe, const ProbeView& view, const ViewHull& hull,
                                const ProbeSamples& samples,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& options);

// After stage 6: a kept simplification step whose corners reach past twice
// kMaxReachOverFarthestSeen x farthestSeenMeters ends the simplification there (every later
// step drops more planes, so it holds this one and reaches as far): those steps are dropped
// and the selection runs again. The step kept gets its corners. Other kinds fit around the
// points seen and cannot reach far.
void dropStepsReachingFar(ProbeProxyBuild& build, glm::dvec3 captureMeters,
                          double farthestSeenMeters, const ProxyBuildOptions& options);

// Stage 7: the kept convex proxy gets its corners and triangles (engines and Blender draw
// it); one that has none keeps the aabb candidate instead. A finding when the capture point is
// not strictly inside the kept proxy.
void finishKeptProxy(ProbeProxyBuild& build, glm::dvec3 captureMeters);

}  // namespace probeproxy
