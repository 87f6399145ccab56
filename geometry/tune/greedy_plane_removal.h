#pragma once
// Simplifying a convex proxy by error, not by geometry: starting from all of a hull's planes,
// repeatedly drop the half-space whose removal raises the probe's mean sample cost the least
// (sample_cost.h), keeping the proxy bounded. Dropping a half-space keeps the result convex and
// closed by construction, and the sequence gives one candidate for every plane count.

#include "core/proxy/convex_proxy.h"
#include "geometry/evaluation/reflection_sample.h"

#include <functional>
#include <span>
#include <vector>

namespace probeproxy {

struct PlaneRemovalStep {
  std::vector<ProxyPlane> planes;  // the planes still kept, in the order of the input
  double meanCostDeg = 0.0;        // over the fitting samples
};

// steps[0] holds all input planes; each next step has one plane fewer, down to `minPlanes` or
// until no plane can go without the rest failing `isAcceptable` (bounded, and not reaching
// absurdly far: see farthestExitMeters).
std::vector<PlaneRemovalStep> greedyPlaneRemoval(
    const std::vector<ProxyPlane>& planes, glm::dvec3 captureMeters,
    std::span<const ReflectionSample> samples, int minPlanes,
    const std::function<bool(const std::vector<ProxyPlane>&)>& isAcceptable);

}  // namespace probeproxy
