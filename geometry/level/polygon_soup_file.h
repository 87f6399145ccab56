#pragma once
// OFF and PLY level meshes, read here rather than through Assimp: on short or lying files (a
// PLY cut mid-header, a binary PLY declaring more faces than it holds, an OFF cut mid-face)
// Assimp loops, reads past the end or asserts. PLY goes through CGAL's reader once
// ply_claims.h has checked what the file claims; OFF through off_file.h (CGAL's OFF scanner
// failed under fuzzing). Every index is checked: a negative or out-of-range vertex index is an
// error naming the face. Faces are triangulated as fans.

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
