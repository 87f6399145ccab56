#pragma once
// Stage 4 of the proxy build: every simplification of the hull's planes and of the planes of
// the walls the probe sees (the inner walls of a concave room among them), down to a
// tetrahedron; the error on the fitting samples decides which planes stay
// (geometry/tune/greedy_plane_removal.h). One `convex_<planes>` candidate per plane count.

#include "core/proxy/proxy_candidate.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/probe_proxies/probe_view.h"

#include <span>
#include <vector>

namespace probeproxy {

// A proxy may reach past what the probe sees (an open end of a corridor), but not far: no
// farther than this many times the farthest point seen, along every direction PlaneReach
// samples.
inline constexpr double kMaxReachOverFarthestSeen = 2.0;

// The planes simplification starts from: the hull's, without its thin bevels (under 0.2% of
// its area, unless the rest would not be bounded), each wall plane replacing the hull facets it
// matches.
std::vector<ProxyPlane> startingPlanes(const ConvexProxy& hull, const ProbeView& view);

// convex_k candidates from the most planes to the fewest, errors not measured yet; their
// buildMs is the simplification's time up to that step. With `holdFloor` the starting planes
// first move out to hold the fit samples' shading points (hold_shading_points.h), so no step
// misses a lookup from the floor it was fitted to.
std::vector<ProxyCandidate> simplifyHull(const ConvexProxy& hull, const ProbeView& view,
                                         std::span<const ReflectionSample> fitSamples,
                                         bool holdFloor, double& simplifyMs);

}  // namespace probeproxy
