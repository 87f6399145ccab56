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

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <span>

namespace probeproxy {

inline constexpr double kMissErrorDeg = 180.0;  // a lookup with no proxy hit (the red pixel)

struct SurveyProbe {  // what the generic blend needs of one probe
  glm::dvec3 captureMeters{0.0};
  InfluenceVolume influence;
  ProxyShape proxy;
};

// What one weighted probe shows at a sample: whether its cubemap holds the true hit (Godot's
// faces stop at their far planes), whether the hit is hidden from its capture point, and its
// lookup error (NaN: a miss). `hidden` is read only when captured, `errorDeg` only when seen.
struct ProbeSight {
  bool captured = true;
  bool hidden = false;
  double errorDeg = std::numeric_limits<double>::quiet_NaN();
};

// A sample's error from its blend (`weights`: each with .probe and .weight) and what each
// weighted probe shows there (`sightOf(probe)`); its heaviest probe is the first seen of the
// largest weight. A probe whose cubemap stops short of the true hit shows its clear colour
// there: that weight is the fallback's, as where no probe reaches.
template <typename Weights, typename SightOf>
SurveySampleError sampleErrorOfBlend(const Weights& weights, double fallbackWeight,
                                     const SightOf& sightOf) {
  SurveySampleError e;
  e.uncoveredWeight = fallbackWeight;
  if (weights.empty()) {
    e.uncovered = true;
    e.uncoveredWeight = 1.0;
    return e;
  }
  double weightedSum = 0.0, visibleWeight = 0.0, heaviest = 0.0;
  for (const auto& w : weights) {
    const ProbeSight sight = sightOf(w.probe);
    if (!sight.captured) {
      e.uncoveredWeight += w.weight;
      continue;
    }
    if (sight.hidden) {
      e.occludedWeight += w.weight;
      continue;
    }
    weightedSum += w.weight * (std::isnan(sight.errorDeg) ? kMissErrorDeg : sight.errorDeg);
    visibleWeight += w.weight;
    if (w.weight > heaviest) {
      heaviest = w.weight;
      e.heaviestProbe = w.probe;
    }
  }
  if (visibleWeight > 0.0) {
    e.errorDeg = weightedSum / visibleWeight;
  } else {
    e.occludedWeight = std::max(0.0, 1.0 - e.uncoveredWeight);  // the rest, up to rounding
  }
  return e;
}

// The fades of a sample's probes summed by what each shows there: all that an average of the
// fades (normalizedFades, Godot 3) needs, so that one probe can be added or taken away in one
// step. averaged() is sampleErrorOfBlend(normalizedFades(fades), sights) up to rounding.
struct FadeSums {
  double all = 0.0, visible = 0.0, visibleError = 0.0, hidden = 0.0, uncaptured = 0.0;
  int count = 0, visibleCount = 0;  // exact where a difference of sums is not

  void add(double fade, const ProbeSight& sight, int sign) {
    all += sign * fade;
    count += sign;
    if (!sight.captured) {
      uncaptured += sign * fade;
    } else if (sight.hidden) {
      hidden += sign * fade;
    } else {
      const double error = std::isnan(sight.errorDeg) ? kMissErrorDeg : sight.errorDeg;
      visible += sign * fade;
      visibleError += sign * fade * error;
      visibleCount += sign;
    }
  }

  SurveySampleError averaged() const {
    SurveySampleError e;
    if (count == 0) {
      e.uncovered = true;
      e.uncoveredWeight = 1.0;
      return e;
    }
    e.uncoveredWeight = uncaptured / all;
    if (visibleCount > 0) {
      e.errorDeg = visibleError / visible;
      e.occludedWeight = hidden / all;
    } else {
      e.occludedWeight = std::max(0.0, 1.0 - e.uncoveredWeight);
    }
    return e;
  }
};

// What probe `probe` of the model shows at the sample, computed as far as it is read.
ProbeSight engineProbeSight(const LevelRayCaster& level, const EngineProbe& probe,
                            const ReflectionSample& sample);

// The same, with `hidden()` saying whether the sample's true hit is hidden from the probe's
// capture point (trueHitHiddenFrom: one ray), asked only where it is read: a caller that judges
// many probes sharing capture points casts each ray once (geometry/survey/capture_sights.h).
ProbeSight engineProbeSight(const EngineProbe& probe, const ReflectionSample& sample,
                            const std::function<bool()>& hidden);

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

// The same, with `hiddenFrom(probe)` saying whether the sample's true hit is hidden from the
// capture point of the model's probe `probe` (geometry/survey/capture_sights.h keeps them).
SurveySampleError blendedSampleError(const EngineModel& model, const ReflectionSample& sample,
                                     const std::function<bool(int)>& hiddenFrom);

}  // namespace probeproxy
