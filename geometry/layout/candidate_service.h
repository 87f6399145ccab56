#pragma once
// What one candidate probe would give the floor near it: its proxy, built as `build` builds
// one for a sphere of influence of `fitMeters` (fitted on the floor connected to the capture
// point) but coarse, and its lookup error on every floor sample within the layout's reach whose
// true hit it sees (evaluate_shape.h's angle; a miss is 180 degrees). Samples it cannot see it
// cannot serve, whatever its proxy. A small fit region models one room exactly, a large one
// several rooms roughly; the cover chooses between them by the floor each serves.

#include "core/proxy/proxy_shape.h"
#include "core/scene/probe.h"
#include "geometry/layout/layout_options.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/floor_samples.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

struct CandidateService {
  glm::dvec3 captureMeters{0.0};
  double fitMeters = 0.0;  // the radius of the floor its proxy was fitted to
  ProxyShape proxy;
  std::vector<std::uint32_t> samples;  // indices into the floor samples, ascending
  std::vector<float> errorDeg;         // samples[i]'s error
  double buildMs = 0.0;                // proxy and evaluation
};

CandidateService serveFloor(const LevelRayCaster& level, glm::dvec3 captureMeters,
                            double fitMeters, std::span<const FloorSample> samples,
                            const LayoutOptions& options);

// The sphere a candidate's proxy is fitted to: the floor connected to the capture point in it.
Probe candidateFitProbe(glm::dvec3 captureMeters, double fitMeters);

}  // namespace probeproxy
