#include "plugin/jobs/measure_settings.h"

#include "core/scene/scene_limits.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace probeproxy::jobs {

namespace {

// Where a floor's grid is set apart (validate's rules, layout's coarse candidates' floor).
MeasureSettings playerOf(MeasureSettings m) {
  m.gridSpacingMeters.reset();
  return m;
}

}  // namespace

MeasureSettings resolvedMeasureSettings(const MeasureSettings& given, const Scene& scene,
                                        const LevelMesh& level) {
  MeasureSettings fromLevel = level.gamePlayer;
  fromLevel.seedPointsMeters = level.spawnPointsMeters;
  return overriding(given, overriding(scene.measuredWith, fromLevel));
}

void applyMeasureSettings(const MeasureSettings& m, WalkableFloorOptions& floor) {
  if (m.gridSpacingMeters) floor.gridSpacingMeters = *m.gridSpacingMeters;
  if (m.stepHeightMeters) floor.stepHeightMeters = *m.stepHeightMeters;
  if (m.headClearanceMeters) floor.headClearanceMeters = *m.headClearanceMeters;
  raiseKneeOverStep(floor);
}

void applyMeasureSettings(const MeasureSettings& m, SurveyOptions& survey) {
  applyMeasureSettings(m, survey.floor);
  if (!m.seedPointsMeters.empty()) survey.seedPointsMeters = m.seedPointsMeters;
  if (m.eyeHeightMeters) survey.eyeHeightMeters = *m.eyeHeightMeters;
  if (m.toleranceDeg) survey.toleranceDeg = *m.toleranceDeg;
}

void applyMeasureSettings(const MeasureSettings& m, ValidateOptions& validate) {
  if (!m.seedPointsMeters.empty()) validate.seedPointsMeters = m.seedPointsMeters;
  if (m.gridSpacingMeters) validate.gridSpacingMeters = *m.gridSpacingMeters;
  if (m.toleranceDeg) validate.toleranceDeg = *m.toleranceDeg;
  applyMeasureSettings(playerOf(m), validate.walkedFloor);
}

void applyMeasureSettings(const MeasureSettings& m, LayoutOptions& layout) {
  applyMeasureSettings(playerOf(m), layout.floor);
  if (m.toleranceDeg) layout.toleranceDeg = *m.toleranceDeg;
}

void checkGivenSeeds(const MeasureSettings& given) {
  for (const glm::dvec3& s : given.seedPointsMeters) {
    if (!(std::max({std::abs(s.x), std::abs(s.y), std::abs(s.z)}) <= kMaxSceneMeters)) {
      throw InputError("--seed", "a seed point is past " + std::to_string(int(kMaxSceneMeters)) +
                                     " m from the origin (the limit of a scene)");
    }
  }
}

MeasureSettings measuredWith(const SurveyOptions& survey, std::vector<glm::dvec3> seedsMeters) {
  MeasureSettings m;
  m.seedPointsMeters = std::move(seedsMeters);
  m.gridSpacingMeters = survey.floor.gridSpacingMeters;
  m.stepHeightMeters = survey.floor.stepHeightMeters;
  m.headClearanceMeters = survey.floor.headClearanceMeters;
  m.eyeHeightMeters = survey.eyeHeightMeters;
  m.toleranceDeg = survey.toleranceDeg;
  return m;
}

}  // namespace probeproxy::jobs
