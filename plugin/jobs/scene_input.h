#pragma once
// What a job works on: a scene, read from its file (the CLI) or handed over in memory (the
// add-on, whose scene lives in Blender), and its level: the scene's own mesh files, loaded as
// the CLI loads them, or parts a front end hands over (Blender meshes already in world metres).

#include "core/scene/scene.h"
#include "geometry/level/level_mesh.h"

#include <filesystem>
#include <optional>
#include <variant>
#include <vector>

namespace probeproxy::jobs {

// One part of a handed-over level: an index into scene.level, or triangles in world metres.
using LevelSource = std::variant<std::size_t, LevelMesh>;

struct SceneInput {
  std::filesystem::path file;                     // read when `scene` is empty
  std::optional<Scene> scene;                     // in memory, already checked (parseSceneFile)
  std::optional<std::vector<LevelSource>> level;  // parts in order; empty: the scene's meshes
};

// The scene: `scene` when given, else the file read and checked. Throws InputError.
Scene readSceneInput(const SceneInput& input);

// The level: the parts in order, or every mesh of the scene. Throws InputError for an
// unreadable mesh, an index past scene.level, or a level with no triangles.
LevelMesh loadSceneLevel(const Scene& scene, const SceneInput& input);

}  // namespace probeproxy::jobs
