#include "geometry/probe_proxies/select_proxy.h"

#include "geometry/probe_proxies/authored_proxy_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
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
           (!o.layoutShapesOnly || layoutChoosesAmong(candidates[i].shape));
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

std::string overToleranceFinding(const std::vector<ProxyCandidate>& candidates, std::size_t kept,
                                 const ProxyBuildOptions& o) {
  if (kept >= candidates.size() || meetsTolerance(candidates[kept].error, o)) return {};
  if (candidates[kept].origin == CandidateOrigin::Authored && !o.regenerate) return {};
  // Nothing measured (no sample the probe sees): the view's own findings say why.
  if (!std::isfinite(candidates[kept].error.p95Deg)) return {};
  const auto degrees = [](double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f deg", d);
    return std::string(text);
  };
  const auto percent = [](double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
    return std::string(text);
  };
  const ErrorFigures& k = candidates[kept].error;
  const bool p95Within = std::isfinite(k.p95Deg) && k.p95Deg <= o.toleranceDeg;
  std::string line =
      "kept " + candidateName(candidates[kept]) + " at p95 " + degrees(k.p95Deg) +
      (p95Within ? ", missing " + percent(k.missRate) + " of the samples (over the " +
                       percent(o.maxMissRate) + " allowed)"
                 : ", over the " + degrees(o.toleranceDeg) + " tolerance") +
      ": no candidate meets both";
  // The refused candidate with the lowest p95, and what refused it.
  std::size_t nearest = candidates.size();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (i == kept || candidates[i].origin == CandidateOrigin::Authored ||
        !std::isfinite(candidates[i].error.p95Deg))
      continue;
    if (nearest == candidates.size() ||
        candidates[i].error.p95Deg < candidates[nearest].error.p95Deg)
      nearest = i;
  }
  if (nearest != candidates.size() && candidates[nearest].error.p95Deg < k.p95Deg) {
    const ProxyCandidate& n = candidates[nearest];
    line += " (the nearest, " + candidateName(n) + " at p95 " + degrees(n.error.p95Deg);
    if (n.error.missRate > o.maxMissRate) {
      line += ", misses " + percent(n.error.missRate) + " of the samples, over the " +
              percent(o.maxMissRate) + " allowed; --max-miss-rate";
    } else if (planeCount(n.shape) > o.maxPlanes) {
      line += ", has " + std::to_string(planeCount(n.shape)) + " planes, over --max-planes " +
              std::to_string(o.maxPlanes);
    } else {
      line +=
          ", no lower in mean error (misses at 180 deg), which decides among those that miss "
          "the tolerance";
    }
    line += ")";
  }
  return line +
         "; where one probe serves more than one room, a second probe (validate's split_probe), "
         "or `layout --keep-authored`, would meet it";
}

}  // namespace probeproxy
