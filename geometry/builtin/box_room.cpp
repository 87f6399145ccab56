#include "geometry/builtin/box_room.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <limits>

namespace probeproxy {

LevelMesh boxRoom(glm::vec3 lo, glm::vec3 hi, const std::string& name) {
  LevelMesh room;
  for (int i = 0; i < 8; ++i) {
    room.positionsMeters.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y,
                                      i & 4 ? hi.z : lo.z);
  }
  // Corner i has bit 0 = x, bit 1 = y, bit 2 = z. Each quad is listed counter-clockwise as seen
  // from inside the room, so the counter-clockwise normal points inwards.
  const glm::uvec4 quads[6] = {
      {0, 2, 6, 4},  // x = lo, normal +x
      {1, 5, 7, 3},  // x = hi, normal -x
      {0, 4, 5, 1},  // y = lo, normal +y
      {2, 3, 7, 6},  // y = hi, normal -y
      {0, 1, 3, 2},  // z = lo (floor), normal +z
      {4, 6, 7, 5},  // z = hi (ceiling), normal -z
  };
  for (const glm::uvec4& q : quads) {
    room.triangles.emplace_back(q.x, q.y, q.z);
    room.triangles.emplace_back(q.x, q.z, q.w);
  }
  room.parts.push_back({name, {}, 0, static_cast<std::uint32_t>(room.triangles.size())});
  return room;
}

double boxRoomDistance(glm::dvec3 lo, glm::dvec3 hi, glm::dvec3 p, glm::dvec3 d) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] > 0) nearest = std::min(nearest, (hi[axis] - p[axis]) / d[axis]);
    if (d[axis] < 0) nearest = std::min(nearest, (lo[axis] - p[axis]) / d[axis]);
  }
  return nearest;
}

}  // namespace probeproxy
