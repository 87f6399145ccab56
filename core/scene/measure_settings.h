#pragma once
// What defines the floor a level's figures are measured on, and the tolerance they are judged
// by: where players enter, the floor grid, the player's step, height and eyes. A layout records
// the values it measured with in the scene it writes (`measured_with`), so that a later survey,
// validate or add-on run of that scene measures the same floor and judges by the same
// tolerance; a user's option overrides the scene, the scene the level's game (a Quake 3 BSP's
// player), the game the defaults. Unset members say nothing.

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace probeproxy {

struct MeasureSettings {
  std::vector<glm::dvec3> seedPointsMeters;  // world frame; empty: not said
  std::optional<double> gridSpacingMeters;
  std::optional<double> stepHeightMeters;
  std::optional<double> headClearanceMeters;
  std::optional<double> eyeHeightMeters;
  std::optional<double> toleranceDeg;

  bool empty() const {
    return seedPointsMeters.empty() && !gridSpacingMeters && !stepHeightMeters &&
           !headClearanceMeters && !eyeHeightMeters && !toleranceDeg;
  }
};

// Each member from `first` where it says something, else from `then`.
inline MeasureSettings overriding(const MeasureSettings& first, const MeasureSettings& then) {
  MeasureSettings m = first;
  if (m.seedPointsMeters.empty()) m.seedPointsMeters = then.seedPointsMeters;
  if (!m.gridSpacingMeters) m.gridSpacingMeters = then.gridSpacingMeters;
  if (!m.stepHeightMeters) m.stepHeightMeters = then.stepHeightMeters;
  if (!m.headClearanceMeters) m.headClearanceMeters = then.headClearanceMeters;
  if (!m.eyeHeightMeters) m.eyeHeightMeters = then.eyeHeightMeters;
  if (!m.toleranceDeg) m.toleranceDeg = then.toleranceDeg;
  return m;
}

}  // namespace probeproxy
