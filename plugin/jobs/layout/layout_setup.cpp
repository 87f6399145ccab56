#include "plugin/jobs/layout/layout_setup.h"

#include "core/errors/input_error.h"
#include "geometry/floor/floor_seed.h"
#include "geometry/scene/scene_file.h"
#include "plugin/jobs/measure_settings.h"
#include "plugin/jobs/scene_input.h"

#include <nlohmann/json.hpp>

namespace probeproxy::jobs {

namespace fs = std::filesystem;

namespace {

bool isSceneFile(const fs::path& file) {
  const std::string name = file.filename().string();
  return name.size() > 11 && name.compare(name.size() - 11, 11, ".scene.json") == 0;
}

// A bare level file is read as the scene that lists only it, so both inputs take one path.
Scene readLevelOrScene(const fs::path& file) {
  if (isSceneFile(file) || file.extension() == ".json") return readSceneFile(file);
  if (!isLevelFile(file)) {
    throw InputError(file, "unsupported level format '" + file.extension().string() +
                               "' (expected a .scene.json, or a level: " + kLevelExtensionsText +
                               ")");
  }
  const fs::path absolute = fs::absolute(file).lexically_normal();
  const nlohmann::json text = {{"probeproxy_scene", 1},
                               {"up", "Z"},
                               {"level", {absolute.string()}},
                               {"probes", nlohmann::json::array()}};
  return parseSceneFile(text.dump(), absolute.string() + ".scene.json");
}

}  // namespace

LayoutSetup prepareLayout(const LayoutJobOptions& o) {
  LayoutSetup s;
  s.inMemory = o.levelOrScene.empty();
  const bool inMemory = s.inMemory;
  s.input = inMemory ? readSceneInput(o.input) : readLevelOrScene(o.levelOrScene);
  const Scene& input = s.input;
  if (o.layout.keepAuthored && input.probes.empty())
    throw InputError(inMemory ? input.file : o.levelOrScene,
                     "--keep-authored: the scene has no probes to keep");
  s.level = std::make_unique<LevelMesh>(loadSceneLevel(input, inMemory ? o.input : SceneInput{}));
  const LevelMesh& level = *s.level;
  s.rayCaster = std::make_unique<LevelRayCaster>(level);
  const LevelRayCaster& rayCaster = *s.rayCaster;
  // The user's floor and player, else the scene's (a layout laid out again), else the level's
  // game; the tolerance likewise.
  const MeasureSettings measure = resolvedMeasureSettings(o.given, input, level);
  s.layout = o.layout;
  s.survey = o.survey;
  applyMeasureSettings(measure, s.layout);
  applyMeasureSettings(measure, s.survey);
  checkWithSceneSettings(input, [&] {
    s.layout.check();
    s.survey.check();
  });
  // Players enter where the user, the scene or the level says (its spawn points); a level
  // without them (an OBJ room) at its probes; a bare mesh on its largest floor region.
  std::vector<glm::dvec3>& seeds = s.seedsMeters;
  const auto seedFrom = [&](const std::vector<glm::dvec3>& points, const char* source) {
    if (!seeds.empty() || points.empty()) return;
    seeds = points;
    s.seededFrom = source;
  };
  seedFrom(o.given.seedPointsMeters, "option");
  seedFrom(input.measuredWith.seedPointsMeters, "scene");
  seedFrom(level.spawnPointsMeters, "spawn points");
  std::vector<glm::dvec3> captures;
  for (const Probe& p : input.probes) captures.push_back(p.captureMeters);
  seedFrom(captures, "probes");
  if (seeds.empty()) {
    std::vector<glm::dvec3> regions;
    for (const FloorSeed& seed : floorRegionSeeds(level, rayCaster, s.survey.floor))
      regions.push_back(seed.pointMeters);
    seedFrom(regions, "the level's floor regions");
  }
  if (seeds.empty())
    throw InputError(inMemory ? input.file : o.levelOrScene,
                     "no walkable floor: the level has no spawn points, the scene no probes, and "
                     "no upward face holds a floor a player fits on (give one with --seed X,Y,Z)");

  return s;
}

}  // namespace probeproxy::jobs
