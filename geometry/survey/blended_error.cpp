#include "geometry/survey/blended_error.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"

#include <cmath>

namespace probeproxy {

SurveySampleError blendedSampleError(const LevelRayCaster& level,
                                     std::span<const SurveyProbe> probes,
                                     std::span<const InfluenceVolume> volumes,
                                     const ReflectionSample& sample, const BlendOptions& blend) {
  SurveySampleError e;
  const std::vector<ProbeWeight> weights =
      blendWeights(volumes, sample.xMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters), blend);
  if (weights.empty()) {
    e.uncovered = true;
    return e;
  }
  double weightedError = 0.0, visibleWeight = 0.0;
  for (const ProbeWeight& w : weights) {
    const SurveyProbe& probe = probes[static_cast<std::size_t>(w.probe)];
    if (trueHitHiddenFrom(level, probe.captureMeters, sample)) {
      e.occludedWeight += w.weight;
      continue;
    }
    const double error = angularErrorDeg(probe.proxy, probe.captureMeters, sample);
    weightedError += w.weight * (std::isnan(error) ? kMissErrorDeg : error);
    visibleWeight += w.weight;
  }
  if (visibleWeight > 0.0) {
    e.errorDeg = weightedError / visibleWeight;
  } else {
    e.occludedWeight = 1.0;  // the weights sum to 1 up to rounding: say it exactly
  }
  return e;
}

}  // namespace probeproxy
