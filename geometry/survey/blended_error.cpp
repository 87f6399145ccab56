#include "geometry/survey/blended_error.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"

namespace probeproxy {

SurveySampleError blendedSampleError(const LevelRayCaster& level,
                                     std::span<const SurveyProbe> probes,
                                     std::span<const InfluenceVolume> volumes,
                                     const ReflectionSample& sample, const BlendOptions& blend) {
  const std::vector<ProbeWeight> weights =
      blendWeights(volumes, sample.xMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters), blend);
  return sampleErrorOfBlend(weights, 0.0, [&](int i) {
    const SurveyProbe& p = probes[static_cast<std::size_t>(i)];
    ProbeSight sight;
    sight.hidden = trueHitHiddenFrom(level, p.captureMeters, sample);
    if (!sight.hidden) sight.errorDeg = angularErrorDeg(p.proxy, p.captureMeters, sample);
    return sight;
  });
}

ProbeSight engineProbeSight(const EngineProbe& probe, const ReflectionSample& sample,
                            const std::function<bool()>& hidden) {
  ProbeSight sight;
  sight.captured = sample.hitsSky || capturedAt(probe, sample.trueHitMeters);
  if (!sight.captured) return sight;
  sight.hidden = hidden();
  if (!sight.hidden) sight.errorDeg = engineLookupErrorDeg(probe, sample);
  return sight;
}

ProbeSight engineProbeSight(const LevelRayCaster& level, const EngineProbe& probe,
                            const ReflectionSample& sample) {
  return engineProbeSight(probe, sample,
                          [&] { return trueHitHiddenFrom(level, probe.captureMeters, sample); });
}

SurveySampleError blendedSampleError(const EngineModel& model, const ReflectionSample& sample,
                                     const std::function<bool(int)>& hiddenFrom) {
  const EngineBlend blend = model.blend(sample.xMeters, sample.eyeMeters);
  return sampleErrorOfBlend(blend.weights, blend.fallbackWeight, [&](int i) {
    return engineProbeSight(model.probes[static_cast<std::size_t>(i)], sample,
                            [&] { return hiddenFrom(i); });
  });
}

SurveySampleError blendedSampleError(const LevelRayCaster& level, const EngineModel& model,
                                     const ReflectionSample& sample) {
  return blendedSampleError(model, sample, [&](int i) {
    return trueHitHiddenFrom(level, model.probes[static_cast<std::size_t>(i)].captureMeters,
                             sample);
  });
}

}  // namespace probeproxy
