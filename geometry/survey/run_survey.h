#pragma once
// `survey`: what a player sees across the whole level (DESIGN.md, "Level-wide error"). The
// walkable floor (walkable_floor.h) is flood-filled from the seed points, sampled area-uniform
// with mirror_floor views (floor_samples.h), and every sample shaded as the runtime shades it:
// the covering probes blended, each through its proxy (blended_error.h). Deterministic apart
// from `seconds`: the same scene and options give the same figures and cells, whatever the
// thread count.

#include "core/scene/scene.h"
#include "geometry/engines/engine_model.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/blended_error.h"
#include "geometry/survey/floor_samples.h"
#include "geometry/survey/survey_options.h"
#include "geometry/survey/survey_result.h"

#include <functional>
#include <span>

namespace probeproxy {

// Checks the options, resolves each probe's proxy (survey_proxies.h) or, under an engine's
// model (options.engine), each probe's presets for that engine, and surveys. Throws
// InputError when no seed point stands over walkable floor.
// `onProbeBuilt(done, total)` reports the proxy builds, the slow part on real levels.
SurveyResult runSurvey(const Scene& scene, const LevelRayCaster& level,
                       const SurveyOptions& options,
                       const std::function<void(std::size_t, std::size_t)>& onProbeBuilt = {});

// The same with the probes given: what runSurvey does once the proxies are known (the generic
// model; options.engine is not read).
SurveyResult surveyProbes(std::span<const SurveyProbe> probes, const LevelRayCaster& level,
                          const SurveyOptions& options);

// What a survey of `cells` floor cells with `samplesPerCell` samples each takes at its peak,
// the program included (fitted on the generated towns of 1 and 25 ha: 139 MB before the level,
// about 210 bytes a cell and 180 a sample), and the check of that against `budgetBytes`
// (core/io/memory_budget.h): InputError naming the floor when it would not fit.
inline constexpr std::uint64_t kSurveyBytesPerCell = 256;
std::uint64_t surveyMemoryBytes(std::size_t cells, int samplesPerCell);
void requireSurveyMemory(const WalkableFloor& floor, int samplesPerCell, std::uint64_t budgetBytes);

// The walkable floor and its samples, which every survey of one level with the same seeds and
// floor options shares: seeded from options.seedPointsMeters, else from `seedPointsMeters`
// (the scene's capture points). Throws InputError as runSurvey.
struct SurveyFloor {
  WalkableFloor floor;
  std::vector<FloorSample> samples;  // cell by cell, samplesPerCell each
  int samplesPerCell = 0;
  double seconds = 0.0;  // to prepare it
};
SurveyFloor prepareSurveyFloor(std::span<const glm::dvec3> seedPointsMeters,
                               const LevelRayCaster& level, const SurveyOptions& options);

class CaptureSights;

// The survey of a prepared floor under an engine's model; with `sights` (made for `floor`), each
// ray from a capture point to a sample's true hit is cast once over every survey sharing it.
SurveyResult surveyModel(const EngineModel& model, const SurveyFloor& floor,
                         const LevelRayCaster& level, const SurveyOptions& options,
                         CaptureSights* sights = nullptr);

}  // namespace probeproxy
