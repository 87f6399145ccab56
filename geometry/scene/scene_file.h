#pragma once
// The scene file (`*.scene.json`, schema in docs/cli_and_formats.md "Scene file"): reading with
// full validation, and writing in the one canonical layout.
//
// Frames: a Scene is always in the world frame (Z up, metres); the file may be Y-up and in
// other units (`up`, `meters_per_unit`). Reading converts to the world frame once
// (core/scene/world_frame.h), writing converts back, so a Scene never holds file units.
//
// Canonical form: the bytes sceneFileJson writes (docs/cli_and_formats.md's example is one). It is
// a fixed point: reading a canonical file and writing it again gives the same bytes, whatever its
// `up` and `meters_per_unit`. Written numbers are rounded to 1e-9 of a file unit (15
// significant digits from 1e6 up), so conversion noise such as 30 * 0.01 / 0.01 never shows.

#include "core/scene/scene.h"
#include "core/scene/scene_limits.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace probeproxy {

// Reads and validates `file`. Relative paths in it are resolved against its folder
// (LevelMeshRef::path, AuthoredConvexMesh::mesh), and kept as written beside. Whether the
// mesh files exist is not checked here: the level loader does that, naming the mesh.
// Throws InputError(file, "<JSON path>: <what was expected>, got <what was there>") for the
// first problem found, e.g. "$.probes[1].influence.radius: expected a positive number, got -2".
// A level mesh or map given where a scene goes is refused by name.
Scene readSceneFile(const std::filesystem::path& file);

// What a scene's "level" takes: a mesh (.glb, .gltf, .obj, .ply, .off) or a Quake 3 map (.bsp,
// .pk3), by extension, whatever the case.
bool isLevelFile(const std::filesystem::path& file);
inline constexpr char kLevelExtensionsText[] = ".glb, .gltf, .obj, .ply, .off, .bsp or .pk3";

// The same for bytes already read (the add-on, fuzzers); `file` names them in errors and
// anchors their relative paths.
Scene parseSceneFile(std::string_view bytes, const std::filesystem::path& file);

// The canonical bytes of `scene`'s file: fixed member order (docs/cli_and_formats.md's), 2-space
// indent, values wrapped at 100 columns, trailing newline. Paths are written as they were read
// (`pathAsWritten`, or `path` when that is empty). Does not validate: writeSceneFile does.
std::string sceneFileJson(const Scene& scene);

// `scene` as reading it back from `file` would give it: every coordinate as the file spells it
// (to the micrometre). What a layout measures before it writes, so that a survey of the written
// file gives the same figures to the last bit.
Scene sceneAsWritten(const Scene& scene, const std::filesystem::path& file);

// Writes `scene` to `file` atomically (core/io/atomic_write.h). Relative paths are rewritten
// relative to `file`'s folder when it differs from the folder `scene.file` is in. The bytes
// are read back through readSceneFile's validation first, so a Scene the format cannot
// express (duplicate names, a NaN, an inner range past the outer) throws InputError naming
// `file` and the JSON path, and nothing is written.
void writeSceneFile(const Scene& scene, const std::filesystem::path& file);

}  // namespace probeproxy
