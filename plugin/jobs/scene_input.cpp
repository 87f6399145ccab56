#include "plugin/jobs/scene_input.h"

#include "core/errors/input_error.h"
#include "geometry/level/load_level.h"
#include "geometry/scene/scene_file.h"

#include <string>

namespace probeproxy::jobs {

Scene readSceneInput(const SceneInput& input) {
  return input.scene ? *input.scene : readSceneFile(input.file);
}

LevelMesh loadSceneLevel(const Scene& scene, const SceneInput& input) {
  if (!input.level) return loadLevel(scene);
  LevelMesh level;
  for (const LevelSource& source : *input.level) {
    if (const auto* index = std::get_if<std::size_t>(&source)) {
      if (*index >= scene.level.size())
        throw InputError(scene.file, "the scene has no level mesh " + std::to_string(*index));
      const LevelMeshRef& ref = scene.level[*index];
      appendLevelMesh(level, loadLevelMeshRef(ref, scene.metersPerUnit));
    } else {
      appendLevelMesh(level, std::get<LevelMesh>(source));
    }
  }
  if (level.triangles.empty()) throw InputError(scene.file, "the level has no triangles");
  requireLevelWithinLimits(scene.file, level);
  return level;
}

}  // namespace probeproxy::jobs
