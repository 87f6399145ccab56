#include "plugin/jobs/measure_settings.h"

#include <algorithm>

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
  // The wall test between two cells runs above a step: a taller step (Nexuiz's 1.06 m) lifts it.
  if (floor.kneeHeightMeters <= floor.stepHeightMeters) {
    floor.kneeHeightMeters = std::min(floor.stepHeightMeters + 0.15,
                                      0.5 * (floor.stepHeightMeters + floor.headClearanceMeters));
  }
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
