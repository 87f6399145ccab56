#include "geometry/probe_proxies/simplify_hull.h"

#include "geometry/fit/polytope_from_planes.h"
#include "geometry/probe_proxies/hold_shading_points.h"
#include "geometry/probe_proxies/stopwatch.h"
#include "geometry/tune/greedy_plane_removal.h"
#include "geometry/tune/plane_reach.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numeric>

namespace probeproxy {

std::vector<ProxyPlane> startingPlanes(const ConvexProxy& hull, const ProbeView& view) {
  // The hull has a thin bevel plane wherever two walls meet between texels; they cost no
  // accuracy and only slow the simplification, so planes under 0.2% of the hull's area start
  // out dropped (kept if the rest would not be bounded).
  std::vector<ProxyPlane> planes;
  const std::vector<double> areas = planeAreasSquareMeters(hull);
  const double totalArea = std::accumulate(areas.begin(), areas.end(), 0.0);
  for (std::size_t i = 0; i < hull.planes.size(); ++i) {
    if (areas[i] >= 0.002 * totalArea) planes.push_back(hull.planes[i]);
  }
  if (!isBounded(planes)) planes = hull.planes;
  // A hull facet on a wall passes through three texel hits and tilts by up to a texel's
  // angle; the wall's own plane (every texel on it averaged) is exact. So a wall plane
  // replaces the hull facets it matches, and the proxy's walls coincide with the level's.
  const double offsetTolerance = 10 * view.toleranceMeters;
  const auto replaceMatches = [&](std::vector<ProxyPlane>& set, const ProxyPlane& p) {
    std::erase_if(set, [&](const ProxyPlane& q) {
      return glm::dot(p.normal, q.normal) > 0.9998 &&
             std::abs(p.offsetMeters - q.offsetMeters) < offsetTolerance;
    });
    set.push_back(p);
  };
  // A wall plane is within a degree of the facets it replaces, so the set stays bounded after
  // every replacement, all but always: test the end result once, and one replacement at a time
  // only when it is not.
  std::vector<ProxyPlane> all = planes;
  for (const ProxyPlane& p : view.wallPlanes) replaceMatches(all, p);
  if (isBounded(all)) return all;
  for (const ProxyPlane& p : view.wallPlanes) {
    std::vector<ProxyPlane> replaced = planes;
    replaceMatches(replaced, p);
    if (isBounded(replaced)) planes = std::move(replaced);
  }
  return planes;
}

std::vector<ProxyCandidate> simplifyHull(const ConvexProxy& hull, const ProbeView& view,
                                         std::span<const ReflectionSample> fitSamples,
                                         bool holdFloor, double& simplifyMs) {
  const Stopwatch time;
  const glm::dvec3 capture = view.captureMeters;
  std::vector<ProxyPlane> start = startingPlanes(hull, view);
  if (holdFloor) start = holdingShadingPoints(std::move(start), fitSamples);
  PlaneReach reach(start, capture);
  // The reach first: it is the cheaper test.
  const PlaneRemovalRule nearTheRoom{[&](const std::vector<ProxyPlane>& p, std::size_t j) {
                                       return reach.farthestWithoutMeters(j) <=
                                                  kMaxReachOverFarthestSeen * view.farthestMeters &&
                                              isBounded(p);
                                     },
                                     [&](std::size_t j) { reach.remove(j); }};
  const std::vector<PlaneRemovalStep> steps =
      greedyPlaneRemoval(start, capture, fitSamples, 4, nearTheRoom);
  simplifyMs = time.ms();
  const double perStepMs = steps.size() > 1 ? simplifyMs / double(steps.size() - 1) : 0.0;
  std::vector<ProxyCandidate> candidates;
  for (std::size_t s = 1; s < steps.size(); ++s) {
    ConvexProxy simplified;
    simplified.planes = steps[s].planes;
    candidates.push_back(
        {CandidateOrigin::Simplified, std::move(simplified), {}, {}, perStepMs * double(s)});
  }
  return candidates;
}

}  // namespace probeproxy
