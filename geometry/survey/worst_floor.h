#pragma once
// What sets a survey's p95: the worst 5% of the shaded floor read by what its reflections reach
// (survey_result.h, WorstFloor). Where a layout's p95 stays high, this says whether a better
// layout could help (the floor of a few probes, reflections a proxy cuts short) or no convex
// proxy of a room can (steps, kerbs and props standing in the room).

#include "core/proxy/proxy_shape.h"
#include "geometry/survey/floor_samples.h"
#include "geometry/survey/survey_result.h"

#include <functional>
#include <span>

namespace probeproxy {

struct SurveyProbeRef {  // what the worst floor needs of the probe a sample's error weighs most
  const ProxyShape* proxy = nullptr;
  int sceneProbe = 0;
};

// `errors[i]` is the error of `samples[i]`; `probeOf(heaviestProbe)` names that probe. The
// floor at `thresholdDeg` (the survey's p95) or over, each sample standing for its shaded area.
WorstFloor worstFloor(std::span<const SurveySampleError> errors,
                      std::span<const FloorSample> samples, double thresholdDeg,
                      const std::function<SurveyProbeRef(int)>& probeOf);

}  // namespace probeproxy
