#pragma once
// Writing a level (or any triangle soup) as a mesh file: .glb, .obj, .ply (binary) or
// .off, chosen by extension, atomically. Coordinates are written so they read back bit-exact.
// Used by the demo to put its built-in level on disk and by the loader's round-trip tests.

#include "core/scene/world_frame.h"
#include "geometry/level/level_mesh.h"

#include <filesystem>

namespace probeproxy {

// `fileUp` is the up axis the file is written in (glTF should be Y, as its specification says).
void writeLevelMeshFile(const LevelMesh& level, const std::filesystem::path& file, UpAxis fileUp);

}  // namespace probeproxy
