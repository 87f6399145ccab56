#pragma once
// Stage 2 of the proxy build: the reflection samples the candidates are fitted on and the ones
// they are reported on. Fitting and reporting use different seeds, so the figures are not
// flattered by fitting to the very samples they are measured on.

#include "core/scene/probe.h"
#include "geometry/build/proxy_build_options.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/raycast/level_ray_caster.h"

#include <vector>

namespace probeproxy {

struct ProbeSamples {
  // mirror_floor then all_surfaces, seed options.samples.seed: fitting sees every surface,
  // not just floors, or a proxy tuned to floor reflections alone would drop walls that floor
  // reflections happen not to reach.
  std::vector<ReflectionSample> fit;
  // Seed + 1000: what every figure is reported on.
  std::vector<ReflectionSample> floor;  // mirror_floor
  std::vector<ReflectionSample> all;    // all_surfaces
};

ProbeSamples drawProbeSamples(const LevelRayCaster& level, const Probe& probe,
                              const ProxyBuildOptions& options);

}  // namespace probeproxy
