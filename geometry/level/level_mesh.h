#pragma once
// The level as one triangle soup in the world frame (Z up, metres). Real levels are
// non-manifold, open, full of duplicate vertices and zero-area triangles: all of it is kept as
// it was authored (ray casting ignores degenerate triangles), and counted so a report can say
// what the level holds.

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace probeproxy {

struct LevelPart {  // one mesh of one file, as its author named it
  std::string name;
  std::filesystem::path file;
  std::uint32_t firstTriangle = 0;
  std::uint32_t triangleCount = 0;
};

struct LevelMesh {
  std::vector<glm::vec3> positionsMeters;  // world frame
  std::vector<glm::uvec3> triangles;       // indices into positionsMeters
  std::vector<LevelPart> parts;            // in load order; together they cover `triangles`
};

struct LevelMeshStats {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t degenerateTriangles = 0;  // zero area (repeated or collinear corners)
  glm::vec3 boundsMinMeters{0.0f};
  glm::vec3 boundsMaxMeters{0.0f};
};

LevelMeshStats measureLevelMesh(const LevelMesh& level);

// Appends `part` to `level`, re-indexing its triangles.
void appendLevelMesh(LevelMesh& level, const LevelMesh& part);

}  // namespace probeproxy
