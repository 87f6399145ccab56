#pragma once
// One floor sample's error as the runtime shades it (docs/methods_and_measures.md, "Level-wide
// error"): the probes that reach the sample, weighted by the renderer's blend, each looked up
// through its own proxy. For probe i, error_i = angle(P_i - C_i, H - C_i) (evaluate_shape.h;
// d* = r when the reflection reaches the sky, so only the infinite lookup is exact there), a
// miss counted as 180 degrees. A probe that cannot see H (or the sky along r) shows something
// else whatever its proxy: its weight is counted as occluded and left out of the average, so
//   errorDeg = sum_visible(w_i * error_i) / sum_visible(w_i),  occludedWeight = sum_hidden(w_i).
// With one probe this is the per-probe measure exactly (an occluded sample is outside the
// error); when every weighted probe is hidden the sample has no error (occludedWeight = 1
// minus the fallback's share). Under an engine model the sky / ambient fallback may take part
// of the reflection (uncoveredWeight): that part is no probe's, so it is left out of the
// average too and counted as uncovered floor.

#include "core/blend/blend_weights.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/engines/engine_model.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/survey_result.h"

#include <span>

namespace probeproxy {

inline constexpr double kMissErrorDeg = 180.0;  // a lookup with no proxy hit (the red pixel)

struct SurveyProbe {  // what the generic blend needs of one probe
  glm::dvec3 captureMeters{0.0};
  InfluenceVolume influence;
  ProxyShape proxy;
};

// The generic model (Lagarde or Enlighten over the probes' influence volumes, kBlendLiftMeters
// above the floor point). `volumes[i]` is `probes[i].influence` (passed apart so blendWeights
// can take a span).
SurveySampleError blendedSampleError(const LevelRayCaster& level,
                                     std::span<const SurveyProbe> probes,
                                     std::span<const InfluenceVolume> volumes,
                                     const ReflectionSample& sample, const BlendOptions& blend);

// Any engine's model (geometry/engines/engine_model.h).
SurveySampleError blendedSampleError(const LevelRayCaster& level, const EngineModel& model,
                                     const ReflectionSample& sample);

}  // namespace probeproxy
