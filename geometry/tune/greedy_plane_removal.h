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

// The caller's rule for which sets of planes may stand (bounded, and not reaching absurdly far:
// see farthestExitMeters). `accepts` is asked about the planes left without input plane j;
// `removed`, if set, hears when plane j went for good, so a rule can keep state per step.
struct PlaneRemovalRule {
  std::function<bool(const std::vector<ProxyPlane>& remaining, std::size_t j)> accepts;
  std::function<void(std::size_t j)> removed;
};

// steps[0] holds all input planes; each next step has one plane fewer, down to `minPlanes` or
// until no plane can go without the rest failing the rule.
std::vector<PlaneRemovalStep> greedyPlaneRemoval(const std::vector<ProxyPlane>& planes,
                                                 glm::dvec3 captureMeters,
                                                 std::span<const ReflectionSample> samples,
                                                 int minPlanes, const PlaneRemovalRule& rule);

}  // namespace probeproxy
