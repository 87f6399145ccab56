#pragma once
// One floor sample's error as the runtime shades it (DESIGN.md, "Level-wide error"): the
// probes whose influence covers the sample, weighted by the blend scheme, each looked up
// through its own proxy. For probe i, error_i = angle(P_i - C_i, H - C_i) (evaluate_shape.h;
// d* = r when the reflection reaches the sky, so only the infinite lookup is exact there), a
// miss counted as 180 degrees. A probe that cannot see H (or the sky along r) shows something
// else whatever its proxy: its weight is counted as occluded and left out of the average, so
//   errorDeg = sum_visible(w_i * error_i) / sum_visible(w_i),  occludedWeight = sum_hidden(w_i).
// With one probe this is the per-probe measure exactly (an occluded sample is outside the
// error); when every weighted probe is hidden the sample has no error (occludedWeight = 1).

#include "core/blend/blend_weights.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/survey_result.h"

#include <span>

namespace probeproxy {

inline constexpr double kMissErrorDeg = 180.0;  // a lookup with no proxy hit (the red pixel)
// Floor points sit on the influence volumes' lower boundary (a box from floor to ceiling);
// weights are taken this far above the floor, as validate's floor rules do.
inline constexpr double kBlendLiftMeters = 0.05;

struct SurveyProbe {  // what the blend needs of one probe
  glm::dvec3 captureMeters{0.0};
  InfluenceVolume influence;
  ProxyShape proxy;
};

// `volumes[i]` is `probes[i].influence` (passed apart so blendWeights can take a span).
SurveySampleError blendedSampleError(const LevelRayCaster& level,
                                     std::span<const SurveyProbe> probes,
                                     std::span<const InfluenceVolume> volumes,
                                     const ReflectionSample& sample, const BlendOptions& blend);

}  // namespace probeproxy
