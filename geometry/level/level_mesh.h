#pragma once
// The level as one triangle soup in the world frame (Z up, metres). Real levels are
// non-manifold, open, full of duplicate vertices and zero-area triangles: all of it is kept as
// it was authored (ray casting ignores degenerate triangles), and counted so a report can say
// what the level holds.

#include "core/scene/measure_settings.h"

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
  // Sky surfaces (BSP levels: faces whose shader has the sky flag), apart from `triangles`:
  // they are not a wall a proxy should fit and rays pass them as they pass any opening, but a
  // reflection that reaches one is known to see the sky. Indices into positionsMeters.
  std::vector<glm::uvec3> skyTriangles;
  // Where players start (BSP levels: the info_player_* entities, team spawns included), world
  // frame: the walkable floor is what a player can reach from them.
  std::vector<glm::dvec3> spawnPointsMeters;
  // The game's own player, where the level comes from a game (a Quake 3 BSP: kQuake3Player):
  // its step, height and eyes define the floor it walks. Unset for a plain mesh.
  MeasureSettings gamePlayer;
  // Whether each face is seen from its front only (BSP levels: the compiler keeps a brush's
  // faces toward the playable space, counter-clockwise from it, so behind a face is solid or
  // the void outside the map). A plain mesh's winding is not trusted.
  bool facesOneSided = false;
};

struct LevelMeshStats {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t degenerateTriangles = 0;  // zero area (repeated or collinear corners)
  std::size_t skyTriangles = 0;
  glm::vec3 boundsMinMeters{0.0f};
  glm::vec3 boundsMaxMeters{0.0f};
};

LevelMeshStats measureLevelMesh(const LevelMesh& level);

// Appends `part` to `level`, re-indexing its triangles.
void appendLevelMesh(LevelMesh& level, const LevelMesh& part);

}  // namespace probeproxy
