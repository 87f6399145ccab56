#pragma once
// OFF and PLY level meshes, read with CGAL's polygon-soup readers rather than Assimp's: on
// short or lying files (a PLY cut mid-header, a binary PLY declaring more faces than it holds,
// an OFF cut mid-face) Assimp loops, reads past the end or asserts, while CGAL's stream-based
// readers stop and say so (issue 17). Every index is checked here: a negative or out-of-range
// vertex index is an error naming the face. Faces are triangulated as fans.

#include "core/scene/world_frame.h"
#include "geometry/level/level_mesh.h"

#include <filesystem>

namespace probeproxy {

// Whether `file` is read here (.off, .ply, any case) rather than through Assimp.
bool isPolygonSoupFile(const std::filesystem::path& file);

// The mesh in the world frame; throws InputError naming the file and the problem.
LevelMesh readPolygonSoupFile(const std::filesystem::path& file, UpAxis fileUp,
                              double metersPerUnit);

}  // namespace probeproxy
