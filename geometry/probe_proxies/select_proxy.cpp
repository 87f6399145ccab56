#include "geometry/probe_proxies/select_proxy.h"

#include "geometry/probe_proxies/authored_proxy_shape.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <tuple>

namespace probeproxy {

namespace {

// Shaders pay per plane; among equal plane counts the simpler test wins.
int methodRank(const ProxyShape& shape) {
  return static_cast<int>(methodOf(shape));  // Method lists the tests from simplest
}

bool meetsTolerance(const ErrorFigures& e, const ProxyBuildOptions& o) {
  return std::isfinite(e.p95Deg) && e.p95Deg <= o.toleranceDeg && e.missRate <= o.maxMissRate;
}

}  // namespace

std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates, const ProxyBuildOptions& o) {
  if (!o.regenerate && !candidates.empty() &&
      candidates.front().origin == CandidateOrigin::Authored)
    return 0;
  const auto complexity = [&](std::size_t i) {
    return std::make_tuple(planeCount(candidates[i].shape), methodRank(candidates[i].shape), i);
  };
  // The fewest planes that meet the tolerance.
  std::size_t best = candidates.size();
  const auto generated = [&](std::size_t i) {
    return candidates[i].origin != CandidateOrigin::Authored &&
           planeCount(candidates[i].shape) <= o.maxPlanes &&
           (!o.sceneShapesOnly || sceneFileCanHold(candidates[i].shape));
  };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || !meetsTolerance(candidates[i].error, o)) continue;
    if (best == candidates.size() || complexity(i) < complexity(best)) best = i;
  }
  if (best != candidates.size()) return best;
  // None does. Two things a player sees decide: how wrong the reflection is over most of the
  // floor (the mean, each miss at 180 degrees) and how wrong its worst twentieth is (the p95
  // with misses). A candidate may not have a worse p95 than the box an engine's box
  // projection would use (the aabb candidate, else the best p95), by more than noise (2% +
  // 0.05 degrees); among those the most accurate by mean, sparing the planes that buy less
  // than 5% of it: a concave room that no convex proxy models gets a simple proxy, not 30
  // planes for a hundredth of a degree. Misses past ten times the allowed rate are a proxy
  // that does not hold the room.
  const auto p95Of = [&](std::size_t i) {
    const double p = candidates[i].error.p95WithMissesDeg;
    return std::isfinite(p) ? p : 1e300;
  };
  const auto meanOf = [&](std::size_t i) {
    const double m = candidates[i].error.meanCostDeg;
    return std::isfinite(m) ? m : 1e300;
  };
  const auto admissible = [&](std::size_t i) {
    return generated(i) && candidates[i].error.missRate <= 10 * o.maxMissRate;
  };
  double p95Limit = 1e300;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (admissible(i)) p95Limit = std::min(p95Limit, p95Of(i));
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (admissible(i) && candidates[i].origin == CandidateOrigin::Aabb)
      p95Limit = std::max(p95Limit, p95Of(i));
  }
  p95Limit = 1.02 * p95Limit + 0.05;
  const auto eligible = [&](std::size_t i) { return admissible(i) && p95Of(i) <= p95Limit; };
  std::size_t mostAccurate = candidates.size();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (eligible(i) && (mostAccurate == candidates.size() || meanOf(i) < meanOf(mostAccurate)))
      mostAccurate = i;
  }
  if (mostAccurate == candidates.size()) return 0;  // none admissible: keep the first
  const double goodEnough = 1.05 * meanOf(mostAccurate) + 0.01;
  const double missesAllowed = candidates[mostAccurate].error.missRate + o.maxMissRate;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!eligible(i) || meanOf(i) > goodEnough || candidates[i].error.missRate > missesAllowed)
      continue;
    if (best == candidates.size() || complexity(i) < complexity(best)) best = i;
  }
  return best;
}

}  // namespace probeproxy
