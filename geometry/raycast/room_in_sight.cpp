#include "geometry/raycast/room_in_sight.h"

#include <algorithm>

namespace probeproxy {

namespace {

constexpr double kViewOffsetMeters = 1.5;
constexpr double kWallGapMeters = 0.2;
constexpr double kUnderCeilingMeters = 0.1;
constexpr double kHighestTargetMeters = 10.0;
constexpr double kEyeHeightMeters = 1.7;

bool seesPoint(const LevelRayCaster& level, std::span<const glm::dvec3> viewpoints,
               glm::dvec3 target) {
  for (const glm::dvec3& v : viewpoints) {
    Ray ray{v, glm::vec3(target - v), 0.0f, 0.999f};
    if (!level.firstHit(ray).hit()) return true;
  }
  return false;
}

}  // namespace

std::vector<glm::dvec3> roomViewpoints(const LevelRayCaster& level, glm::dvec3 capture) {
  std::vector<glm::dvec3> points{capture};
  for (const glm::vec3 d :
       {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
    Ray ray{capture, d, 0.0f, static_cast<float>(kViewOffsetMeters + kWallGapMeters)};
    const RayHit hit = level.firstHit(ray);
    const double reach = hit.hit() ? hit.t - kWallGapMeters : kViewOffsetMeters;
    if (reach > 0.0) points.push_back(capture + reach * glm::dvec3(d));
  }
  return points;
}

RoomTargets roomTargetsOver(const LevelRayCaster& level, glm::dvec3 floorPoint) {
  Ray up{floorPoint, {0.0f, 0.0f, 1.0f}, 1e-3f, static_cast<float>(kHighestTargetMeters)};
  const RayHit ceiling = level.firstHit(up);
  const double height = ceiling.hit() ? ceiling.t - kUnderCeilingMeters : kHighestTargetMeters;
  return {floorPoint + glm::dvec3(0, 0, height),
          floorPoint + glm::dvec3(0, 0, std::min(height, kEyeHeightMeters))};
}

bool roomInSight(const LevelRayCaster& level, std::span<const glm::dvec3> viewpoints,
                 const RoomTargets& targets) {
  return seesPoint(level, viewpoints, targets.underCeilingMeters) ||
         (targets.atEyeHeightMeters != targets.underCeilingMeters &&
          seesPoint(level, viewpoints, targets.atEyeHeightMeters));
}

}  // namespace probeproxy
