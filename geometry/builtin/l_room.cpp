#include "geometry/builtin/l_room.h"

#include <glm/geometric.hpp>

#include <utility>

namespace probeproxy {

namespace {

// Appends the quad a b c d (a planar rectangle, corners in order around it), wound so its
// counter-clockwise normal is `inward`. Zero-area quads (arms of length 0) are left out.
void addQuad(LevelMesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
             glm::vec3 inward) {
  const glm::vec3 normal = glm::cross(b - a, c - a);
  if (glm::length(normal) == 0.0f) return;
  if (glm::dot(normal, inward) < 0.0f) std::swap(b, d);
  const auto first = static_cast<unsigned>(mesh.positionsMeters.size());
  mesh.positionsMeters.insert(mesh.positionsMeters.end(), {a, b, c, d});
  mesh.triangles.emplace_back(first, first + 1, first + 2);
  mesh.triangles.emplace_back(first, first + 2, first + 3);
}

// Floor (facing up) and ceiling (facing down) over the rectangle [x0, x1] x [y0, y1].
void addFloorAndCeiling(LevelMesh& mesh, float x0, float y0, float x1, float y1, float h) {
  addQuad(mesh, {x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}, {0, 0, 1});
  addQuad(mesh, {x0, y0, h}, {x1, y0, h}, {x1, y1, h}, {x0, y1, h}, {0, 0, -1});
}

// A wall from (x0, y0) to (x1, y1), floor to ceiling, facing `inward` (horizontal).
void addWall(LevelMesh& mesh, float x0, float y0, float x1, float y1, float h, glm::vec3 inward) {
  addQuad(mesh, {x0, y0, 0}, {x1, y1, 0}, {x1, y1, h}, {x0, y0, h}, inward);
}

}  // namespace

LevelMesh lRoom(const LRoomSize& size) {
  const auto w = static_cast<float>(size.widthMeters);
  const auto a = static_cast<float>(size.armMeters);
  const auto h = static_cast<float>(size.heightMeters);
  const float far = w + a;
  LevelMesh room;
  addFloorAndCeiling(room, 0, 0, w, w, h);       // corner room
  addFloorAndCeiling(room, w, 0, far, w, h);     // x arm
  addFloorAndCeiling(room, 0, w, w, far, h);     // y arm
  addWall(room, 0, 0, far, 0, h, {0, 1, 0});     // south, along both
  addWall(room, 0, 0, 0, far, h, {1, 0, 0});     // west
  addWall(room, far, 0, far, w, h, {-1, 0, 0});  // x arm's end
  addWall(room, 0, far, w, far, h, {0, -1, 0});  // y arm's end
  addWall(room, w, w, far, w, h, {0, -1, 0});    // x arm's north side (the inner corner)
  addWall(room, w, w, w, far, h, {-1, 0, 0});    // y arm's east side (the inner corner)
  room.parts.push_back({"l_room", {}, 0, static_cast<std::uint32_t>(room.triangles.size())});
  return room;
}

}  // namespace probeproxy
