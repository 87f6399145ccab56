#pragma once
// Stage 2 of the proxy build: the reflection samples the candidates are fitted on and the ones
// they are reported on. Fitting and reporting use different seeds, so the figures are not
// flattered by fitting to the very samples they are measured on.

#include "core/scene/probe.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/probe_proxies/proxy_build_options.h"
#include "geometry/raycast/level_ray_caster.h"

#include <vector>

namespace probeproxy {

struct ProbeSamples {
  // mirror_floor then all_surfaces, seed options.samples.seed, from the floor walkable from the
  // capture point (ReflectionSampleOptions::connectedFloorOnly): a proxy fits the room the
  // probe is in, not the rooms its influence reaches through walls. Fitting sees every
  // surface, not just floors, or a proxy tuned to floor reflections alone would drop walls
  // that floor reflections happen not to reach.
  std::vector<ReflectionSample> fit;
  // Seed + 1000, all the floor the influence covers: what every figure is reported on and the
  // kept proxy chosen by, since the runtime shades all of it with this probe.
  std::vector<ReflectionSample> floor;  // mirror_floor
  std::vector<ReflectionSample> all;    // all_surfaces
};

ProbeSamples drawProbeSamples(const LevelRayCaster& level, const Probe& probe,
                              const ProxyBuildOptions& options);

// One report set alone (`floor` or `all`), as drawProbeSamples draws it.
std::vector<ReflectionSample> drawReportSamples(const LevelRayCaster& level, const Probe& probe,
                                                const ProxyBuildOptions& options, SampleSet set);

// The `fit` set alone, as drawProbeSamples draws it (layout passes the probe with the region it
// fits to as its influence).
std::vector<ReflectionSample> drawFitSamples(const LevelRayCaster& level, const Probe& probe,
                                             const ProxyBuildOptions& options);

}  // namespace probeproxy
