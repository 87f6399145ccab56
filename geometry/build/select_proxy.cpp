#include "geometry/build/select_proxy.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <tuple>

namespace probeproxy {

namespace {

// Shaders pay per plane; among equal plane counts the simpler test wins.
int methodRank(const ProxyShape& shape) {
  const std::string_view id = methodId(shape);
  static constexpr std::string_view order[] = {"infinite", "cheap_k", "sphere",
                                               "aabb",     "obb",     "convex"};
  return static_cast<int>(std::find(std::begin(order), std::end(order), id) - std::begin(order));
}

bool meetsTolerance(const ErrorFigures& e, const ProxyBuildOptions& o) {
  return std::isfinite(e.p95Deg) && e.p95Deg <= o.toleranceDeg && e.missRate <= o.maxMissRate;
}

}  // namespace

std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates, const ProxyBuildOptions& o) {
  if (!o.regenerate && !candidates.empty() && candidates.front().kind == "authored") return 0;
  const auto complexity = [&](std::size_t i) {
    return std::make_tuple(planeCount(candidates[i].shape), methodRank(candidates[i].shape), i);
  };
  // The fewest planes that meet the tolerance.
  std::size_t best = candidates.size();
  const auto generated = [&](std::size_t i) {
    return candidates[i].kind != "authored" && planeCount(candidates[i].shape) <= o.maxPlanes;
  };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || !meetsTolerance(candidates[i].error, o)) continue;
    if (best == candidates.size() || complexity(i) < complexity(best)) best = i;
  }
  if (best != candidates.size()) return best;
  // None does: the most accurate within the plane budget, by mean error (misses at 180
  // degrees), sparing the planes that buy less than 5% of it: a concave room that no convex
  // proxy models gets a simple proxy, not 30 planes for a hundredth of a degree.
  const auto meanOf = [&](std::size_t i) {
    const double m = candidates[i].error.meanCostDeg;
    return std::isfinite(m) ? m : 1e300;
  };
  std::size_t mostAccurate = candidates.size();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || candidates[i].error.missRate > o.maxMissRate) continue;
    if (mostAccurate == candidates.size() || meanOf(i) < meanOf(mostAccurate)) mostAccurate = i;
  }
  if (mostAccurate == candidates.size()) return 0;  // nothing but misses: keep the first
  const double goodEnough = 1.05 * meanOf(mostAccurate) + 0.01;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || candidates[i].error.missRate > o.maxMissRate || meanOf(i) > goodEnough)
      continue;
    if (best == candidates.size() || complexity(i) < complexity(best)) best = i;
  }
  return best;
}

}  // namespace probeproxy
