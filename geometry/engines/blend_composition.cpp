#include "geometry/engines/blend_composition.h"

#include <algorithm>

namespace probeproxy {

namespace {

void add(EngineBlend& blend, int probe, double weight) {
  if (weight > 0.0) blend.weights.push_back({probe, weight});
}

}  // namespace

EngineBlend frontToBack(std::span<const ProbeFade> ordered) {
  EngineBlend blend;
  double left = 1.0;
  for (const ProbeFade& p : ordered) {
    if (!(left > 0.0)) break;  // a full probe in front: nothing shows through
    add(blend, p.probe, p.fade * left);
    left *= 1.0 - p.fade;
  }
  blend.fallbackWeight = left;
  return blend;
}

EngineBlend fillToOne(std::span<const ProbeFade> ordered, double fullAt) {
  EngineBlend blend;
  double filled = 0.0;
  for (const ProbeFade& p : ordered) {
    if (filled >= fullAt) break;
    const double weight = std::min(p.fade, 1.0 - filled);
    add(blend, p.probe, weight);
    filled += std::max(0.0, weight);
  }
  blend.fallbackWeight = filled < fullAt ? 1.0 - filled : 0.0;
  return blend;
}

EngineBlend upToLargestFade(std::span<const ProbeFade> ordered) {
  EngineBlend blend;
  double largest = 0.0;
  for (const ProbeFade& p : ordered) {
    if (largest >= 1.0) break;  // reflection_process computes nothing once the sum reaches 1
    add(blend, p.probe, p.fade - largest);
    largest = std::max(largest, p.fade);
  }
  blend.fallbackWeight = 1.0 - largest;
  return blend;
}

EngineBlend normalizedFades(std::span<const ProbeFade> fades) {
  EngineBlend blend;
  double sum = 0.0;
  for (const ProbeFade& p : fades) sum += p.fade;
  if (!(sum > 0.0)) return blend;  // every fade 0: the environment alone
  for (const ProbeFade& p : fades) add(blend, p.probe, p.fade / sum);
  blend.fallbackWeight = 0.0;
  return blend;
}

}  // namespace probeproxy
