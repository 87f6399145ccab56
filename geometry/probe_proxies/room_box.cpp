#include "geometry/probe_proxies/room_box.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace probeproxy {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double hitDistance(const LevelRayCaster& level, glm::dvec3 from, glm::dvec3 direction,
                   double tMax = kInf) {
  Ray ray{from, glm::vec3(direction), 0.0f, static_cast<float>(tMax)};
  const RayHit hit = level.firstHit(ray);
  return hit.hit() ? double(hit.t) : kInf;
}

}  // namespace

std::array<double, 6> axisWallDistances(const LevelRayCaster& level, glm::dvec3 capture) {
  std::array<double, 6> walls{};
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int sign = 0; sign < 2; ++sign) {
      glm::dvec3 direction(0.0);
      direction[axis] = sign == 0 ? -1.0 : 1.0;
      std::vector<double> reach;
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) {
          glm::dvec3 offset(0.0);
          offset[u] = i * kRoomFanOffsetMeters;
          offset[v] = j * kRoomFanOffsetMeters;
          const double length = std::sqrt(double(i * i + j * j)) * kRoomFanOffsetMeters;
          // A ray whose start the capture point cannot reach stands in another room.
          if (length > 0.0 && hitDistance(level, capture, offset / length, length) < kInf) continue;
          reach.push_back(hitDistance(level, capture + offset, direction));
        }
      std::sort(reach.begin(), reach.end());
      walls[2 * axis + sign] = reach.empty() ? kInf : reach[(reach.size() - 1) / 2];
    }
  }
  return walls;
}

std::optional<BoxShape> roomBox(glm::dvec3 capture, const std::array<double, 6>& walls,
                                std::span<const glm::dvec3> seen) {
  glm::dvec3 seenLo(kInf), seenHi(-kInf);
  for (const glm::dvec3& p : seen) seenLo = glm::min(seenLo, p), seenHi = glm::max(seenHi, p);
  glm::dvec3 lo, hi;
  for (int axis = 0; axis < 3; ++axis) {
    lo[axis] = std::isfinite(walls[2 * axis]) ? capture[axis] - walls[2 * axis] : seenLo[axis];
    hi[axis] =
        std::isfinite(walls[2 * axis + 1]) ? capture[axis] + walls[2 * axis + 1] : seenHi[axis];
    if (!(lo[axis] < capture[axis] && capture[axis] < hi[axis])) return std::nullopt;
  }
  return BoxShape{0.5 * (lo + hi), 0.5 * (hi - lo)};
}

}  // namespace probeproxy
