#pragma once
// The floor and tolerance a job measures with (core/scene/measure_settings.h): the user's
// options first, then what the scene says it was measured with (a layout's scene), then the
// level (its spawn points and its game's player: a Quake 3 BSP's); the options' defaults for
// anything none of them says. survey, validate and layout resolve them the same way, so a
// layout's figures and a later survey of its scene are measured on the same floor.

#include "core/errors/input_error.h"
#include "core/scene/measure_settings.h"
#include "core/scene/scene.h"
#include "geometry/layout/layout_options.h"
#include "geometry/level/level_mesh.h"
#include "geometry/survey/survey_options.h"
#include "geometry/validate/validate_scene.h"

namespace probeproxy::jobs {

MeasureSettings resolvedMeasureSettings(const MeasureSettings& given, const Scene& scene,
                                        const LevelMesh& level);

// Each set member into the options it means; unset ones leave the options as they are.
void applyMeasureSettings(const MeasureSettings& m, WalkableFloorOptions& floor);
void applyMeasureSettings(const MeasureSettings& m, SurveyOptions& survey);
void applyMeasureSettings(const MeasureSettings& m, ValidateOptions& validate);
// The player only (the layout's coarse floor keeps its own grid) and the tolerance.
void applyMeasureSettings(const MeasureSettings& m, LayoutOptions& layout);

// Refuses a seed point past the scene's limit, as the scene file's reader does (InputError
// "--seed").
void checkGivenSeeds(const MeasureSettings& given);

// `options` as the user's settings make them, checked before the scene is read: a bad option is
// one line naming it, at once.
template <class Options>
void checkAsGiven(Options options, const MeasureSettings& given) {
  applyMeasureSettings(given, options);
  options.check();
  checkGivenSeeds(given);
}

// Runs `check` on options that now hold the scene's measured_with: the user's own were checked
// before the scene was read, so a value refused here is the scene's, and the line names its file.
template <class Check>
void checkWithSceneSettings(const Scene& scene, Check check) {
  try {
    check();
  } catch (const InputError& e) {
    if (scene.measuredWith.empty()) throw;
    throw InputError(scene.file, "$.measured_with: " + e.file().string() + ": " + e.problem());
  }
}

// Every member set, as `survey` measured: what a layout writes into its scene.
MeasureSettings measuredWith(const SurveyOptions& survey, std::vector<glm::dvec3> seedsMeters);

}  // namespace probeproxy::jobs
