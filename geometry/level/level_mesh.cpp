#include "geometry/level/level_mesh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <limits>

namespace probeproxy {

LevelMeshStats measureLevelMesh(const LevelMesh& level) {
  LevelMeshStats stats;
  stats.vertices = level.positionsMeters.size();
  stats.triangles = level.triangles.size();
  stats.skyTriangles = level.skyTriangles.size();
  glm::vec3 lo(std::numeric_limits<float>::infinity());
  glm::vec3 hi(-std::numeric_limits<float>::infinity());
  for (const glm::vec3& p : level.positionsMeters) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (!level.positionsMeters.empty()) {
    stats.boundsMinMeters = lo;
    stats.boundsMaxMeters = hi;
  }
  for (const glm::uvec3& t : level.triangles) {
    const glm::vec3 a = level.positionsMeters[t.x];
    const glm::vec3 b = level.positionsMeters[t.y];
    const glm::vec3 c = level.positionsMeters[t.z];
    if (glm::cross(b - a, c - a) == glm::vec3(0.0f)) ++stats.degenerateTriangles;
  }
  return stats;
}

void appendLevelMesh(LevelMesh& level, const LevelMesh& part) {
  level.facesOneSided =
      level.triangles.empty() ? part.facesOneSided : level.facesOneSided && part.facesOneSided;
  const auto vertexOffset = static_cast<std::uint32_t>(level.positionsMeters.size());
  const auto triangleOffset = static_cast<std::uint32_t>(level.triangles.size());
  level.positionsMeters.insert(level.positionsMeters.end(), part.positionsMeters.begin(),
                               part.positionsMeters.end());
  for (const glm::uvec3& t : part.triangles) level.triangles.push_back(t + vertexOffset);
  for (const glm::uvec3& t : part.skyTriangles) level.skyTriangles.push_back(t + vertexOffset);
  level.spawnPointsMeters.insert(level.spawnPointsMeters.end(), part.spawnPointsMeters.begin(),
                                 part.spawnPointsMeters.end());
  level.gamePlayer = overriding(level.gamePlayer, part.gamePlayer);  // the first game's player
  for (LevelPart p : part.parts) {
    p.firstTriangle += triangleOffset;
    level.parts.push_back(std::move(p));
  }
}

}  // namespace probeproxy
