#pragma once
// What `survey` measures and how finely (DESIGN.md, "Measures": level-wide error). Plain data;
// check() throws InputError for a value out of range, so every front end refuses the same
// inputs with the same one-line message.

#include "core/blend/blend_weights.h"
#include "geometry/engines/engine.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/probe_proxies/build_probe_proxy.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace probeproxy {

// Which proxy each probe is looked up through.
enum class SurveyProxies {
  Scene,     // the authored one, else the one `build` keeps (or proxiesJson's, when given)
  Infinite,  // no correction: every probe looked up with r (the baseline)
  BestAabb,  // the `aabb` candidate `build` makes (what box projection in an engine gives)
};

struct SurveyOptions {
  BlendOptions blend;          // Lagarde by default, at most 4 probes
  double toleranceDeg = 5.0;   // over_tolerance_share: floor whose sample error exceeds this
  WalkableFloorOptions floor;  // grid, step height, head clearance
  // Where the flood fill starts (spawn points); empty: the probes' capture points.
  std::vector<glm::dvec3> seedPointsMeters;
  int samplesPerCell = 8;              // floor samples per floor cell, area-uniform in it
  std::size_t maxSamples = 2'000'000;  // fewer per cell (at least 1) on huge floors
  double eyeHeightMeters = 1.7;        // the camera above the floor under a sample
  int maxViewAttempts = 16;  // view directions tried before a sample is seen from straight above
  std::uint32_t seed = 1;
  SurveyProxies proxies = SurveyProxies::Scene;
  std::filesystem::path proxiesJson;  // a `build` export whose kept proxies to use; empty: none
  ProxyBuildOptions build;            // for probes whose proxy is `auto` (and BestAabb)
  // Whose renderer to measure: Generic is the scene's proxies under `blend`; any other engine
  // gets the presets a build exports for it (proxiesJson's, or every probe built now) and
  // blends them by its own rules (geometry/engines/). `proxies` must then be Scene.
  Engine engine = Engine::Generic;
  // What the survey may take (core/io/memory_budget.h); 0: what the process can use.
  std::uint64_t maxMemoryBytes = 0;

  void check() const;
};

}  // namespace probeproxy
