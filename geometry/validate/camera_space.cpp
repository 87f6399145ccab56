#include "geometry/validate/camera_space.h"

#include "geometry/raycast/open_space.h"

#include <vector>

namespace probeproxy {

namespace {

// A walked cell's height is its centre's: within a cell a ramp or a step's edge is this much
// higher or lower (WalkableFloorOptions::stepHeightMeters, the most two cells differ by).
constexpr double kCellHeightToleranceMeters = 0.45;

}  // namespace

void markCameraSpace(const LevelRayCaster& level, const WalkableFloor& walked,
                     double headRoomMeters, std::span<const glm::dvec3> pointsMeters,
                     std::span<char> reachable) {
  const std::vector<VerticalView> views = lookUpAndDown(level, pointsMeters);
  for (std::size_t i = 0; i < pointsMeters.size(); ++i) {
    const double below = views[i].floorBelowMeters;
    reachable[i] =
        below <= headRoomMeters &&
        walked.reaches(pointsMeters[i] - glm::dvec3(0.0, 0.0, below), kCellHeightToleranceMeters);
  }
}

}  // namespace probeproxy
