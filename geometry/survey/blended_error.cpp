#include "geometry/survey/blended_error.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

// `capture(i)`, `error(i)` and `captured(i)` (whether its cubemap holds the true hit) of the
// probe a weight names. A probe whose cubemap stops short of the true hit shows its clear
// colour there: that weight is the fallback's, as where no probe reaches.
template <typename Weights, typename Capture, typename Error, typename Captured>
SurveySampleError weightedError(const LevelRayCaster& level, const ReflectionSample& sample,
                                const Weights& weights, double fallbackWeight,
                                const Capture& capture, const Error& error,
                                const Captured& captured) {
  SurveySampleError e;
  e.uncoveredWeight = fallbackWeight;
  if (weights.empty()) {
    e.uncovered = true;
    e.uncoveredWeight = 1.0;
    return e;
  }
  double weightedSum = 0.0, visibleWeight = 0.0;
  for (const auto& w : weights) {
    if (!captured(w.probe)) {
      e.uncoveredWeight += w.weight;
      continue;
    }
    if (trueHitHiddenFrom(level, capture(w.probe), sample)) {
      e.occludedWeight += w.weight;
      continue;
    }
    const double errorDeg = error(w.probe);
    weightedSum += w.weight * (std::isnan(errorDeg) ? kMissErrorDeg : errorDeg);
    visibleWeight += w.weight;
  }
  if (visibleWeight > 0.0) {
    e.errorDeg = weightedSum / visibleWeight;
  } else {
    e.occludedWeight = std::max(0.0, 1.0 - e.uncoveredWeight);  // the rest, up to rounding
  }
  return e;
}

}  // namespace

SurveySampleError blendedSampleError(const LevelRayCaster& level,
                                     std::span<const SurveyProbe> probes,
                                     std::span<const InfluenceVolume> volumes,
                                     const ReflectionSample& sample, const BlendOptions& blend) {
  const std::vector<ProbeWeight> weights =
      blendWeights(volumes, sample.xMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters), blend);
  const auto probe = [&](int i) -> const SurveyProbe& {
    return probes[static_cast<std::size_t>(i)];
  };
  return weightedError(
      level, sample, weights, 0.0, [&](int i) { return probe(i).captureMeters; },
      [&](int i) { return angularErrorDeg(probe(i).proxy, probe(i).captureMeters, sample); },
      [](int) { return true; });
}

SurveySampleError blendedSampleError(const LevelRayCaster& level, const EngineModel& model,
                                     const ReflectionSample& sample) {
  const EngineBlend blend = model.blend(sample.xMeters, sample.eyeMeters);
  const auto probe = [&](int i) -> const EngineProbe& {
    return model.probes[static_cast<std::size_t>(i)];
  };
  return weightedError(
      level, sample, blend.weights, blend.fallbackWeight,
      [&](int i) { return probe(i).captureMeters; },
      [&](int i) { return engineLookupErrorDeg(probe(i), sample); },
      [&](int i) { return sample.hitsSky || capturedAt(probe(i), sample.trueHitMeters); });
}

}  // namespace probeproxy
