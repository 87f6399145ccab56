#include "core/blend/blend_weights.h"

#include "core/blend/enlighten_distance.h"
#include "core/blend/influence_factor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace probeproxy {

std::string_view blendSchemeName(BlendScheme scheme) {
  return scheme == BlendScheme::Lagarde ? "lagarde" : "enlighten";
}

std::optional<BlendScheme> blendSchemeFromName(std::string_view name) {
  if (name == "lagarde") return BlendScheme::Lagarde;
  if (name == "enlighten") return BlendScheme::Enlighten;
  return std::nullopt;
}

namespace {

struct Candidate {
  int probe = 0;
  double key = 0.0;          // smaller = more influential: a (Lagarde) or distSq (Enlighten)
  double cubicMeters = 0.0;  // tie-break: the smaller volume first
  double raw = 0.0;          // unnormalized weight
};

bool moreInfluential(const Candidate& x, const Candidate& y) {
  return std::tie(x.key, x.cubicMeters, x.probe) < std::tie(y.key, y.cubicMeters, y.probe);
}

// Lagarde's (1 - a) / a, the (1 - a) faded against the next candidate's a_next.
double lagardeWeight(double a, double aNext, bool fade) {
  const double keep =
      fade ? std::min(1.0 - a, std::max(0.0, aNext - a) / kLagardeFadeWidth) : 1.0 - a;
  return keep / a;
}

double enlightenWeight(double distSq, double distSqNext, bool fade) {
  const double weight = 1.0 / (kEnlightenEpsilon + distSq);
  if (!fade) return weight;
  const double octaves =
      std::log2(kEnlightenEpsilon + distSqNext) - std::log2(kEnlightenEpsilon + distSq);
  return weight * std::clamp(octaves, 0.0, 1.0);
}

}  // namespace

std::vector<ProbeWeight> blendWeights(std::span<const InfluenceVolume> volumes, glm::dvec3 p,
                                      const BlendOptions& options) {
  if (options.maxProbes < 1) throw std::invalid_argument("blendWeights: maxProbes must be >= 1");
  const bool lagarde = options.scheme == BlendScheme::Lagarde;

  // Reserved whole: this runs for every point of every blend grid (the survey, the layout's
  // trims and fades), where regrowing the vectors showed in profiles as malloc and free.
  std::vector<Candidate> candidates;
  candidates.reserve(volumes.size());
  bool covered = false;
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    const double a = normalizedDistance(volumes[i], p);
    covered = covered || a < 1.0;
    if (lagarde && a >= 1.0) continue;
    candidates.push_back({static_cast<int>(i), lagarde ? a : enlightenDistanceSq(volumes[i], p),
                          influenceCubicMeters(volumes[i]), 0.0});
  }
  if (!covered) return {};
  std::sort(candidates.begin(), candidates.end(), moreInfluential);

  // In an inner range: 100% (the first after sorting is the smallest such volume).
  if (lagarde && candidates.front().key == 0.0) return {{candidates.front().probe, 1.0}};

  const std::size_t kept = std::min(candidates.size(), static_cast<std::size_t>(options.maxProbes));
  const bool truncated = candidates.size() > kept;
  const double next =
      truncated ? candidates[kept].key : (lagarde ? 1.0 : std::numeric_limits<double>::infinity());
  candidates.resize(kept);

  // fade == false only when every kept candidate ties with the next one (N + 1 identical
  // volumes): the fade would zero them all, so the first N by the tie order stay, unfaded.
  double sum = 0.0;
  for (bool fade : {true, false}) {
    sum = 0.0;
    for (Candidate& c : candidates) {
      c.raw = lagarde ? lagardeWeight(c.key, next, fade) : enlightenWeight(c.key, next, fade);
      sum += c.raw;
    }
    if (sum > 0.0) break;
  }

  std::vector<ProbeWeight> weights;
  weights.reserve(candidates.size());
  for (const Candidate& c : candidates) {
    if (c.raw > 0.0) weights.push_back({c.probe, c.raw / sum});
  }
  std::sort(weights.begin(), weights.end(), [](const ProbeWeight& x, const ProbeWeight& y) {
    return x.weight != y.weight ? x.weight > y.weight : x.probe < y.probe;
  });
  return weights;
}

}  // namespace probeproxy
