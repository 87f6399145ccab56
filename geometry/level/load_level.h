#pragma once
// Reading level meshes (glTF/GLB, OBJ, PLY, OFF; Quake 3 BSP, alone or inside a .pk3: see
// geometry/level/bsp/bsp_level.h) into the world frame. Missing or unreadable
// files, malformed meshes, NaN or infinite coordinates and levels with no triangles throw
// InputError naming the file; messy but finite geometry is loaded as it is.

#include "core/scene/scene.h"
#include "geometry/level/level_mesh.h"

#include <filesystem>

namespace probeproxy {

// Throws InputError naming `source` if `mesh` holds more than kMaxLevelTriangles triangles or
// a vertex past kMaxSceneMeters (core/scene/scene_limits.h). Every loader below calls it.
void requireLevelWithinLimits(const std::filesystem::path& source, const LevelMesh& mesh);

// One mesh file. `fileUp` and `metersPerUnit` say how the file's coordinates map to the world.
LevelMesh loadLevelMeshFile(const std::filesystem::path& file, UpAxis fileUp, double metersPerUnit);

// One level entry of a scene: a BSP (or a .pk3 with `map`) in its own units (1/32 m per unit,
// Z up: `sceneMetersPerUnit` and `ref.up` do not apply), any other mesh through
// loadLevelMeshFile. Throws if a BSP has no solid faces.
LevelMesh loadLevelMeshRef(const LevelMeshRef& ref, double sceneMetersPerUnit);

// Every mesh of the scene's level, in scene order. Throws if the level has no triangles.
LevelMesh loadLevel(const Scene& scene);

}  // namespace probeproxy
