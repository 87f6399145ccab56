// `probeproxy level-info LEVEL [--map maps/NAME.bsp]` (hidden: a utility for scripts, not one
// of the product's verbs). Loads a Quake 3 BSP (or the map inside a .pk3) as `build` would and
// prints, as JSON on stdout, what a scene writer needs and what the corpus table reports:
// triangle counts, load time, the face counts, and every player spawn point and light with
// the floor under it (the first level surface straight below, within 64 m; null if none).

#include "geometry/level/bsp/bsp_level.h"
#include "geometry/raycast/floor_below.h"
#include "geometry/raycast/level_ray_caster.h"
#include "plugin/cli/verb.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

constexpr float kFloorSearchMeters = 64.0f;

struct LevelInfoOptions {
  std::string level;
  std::string map;
};

nlohmann::json vec3Json(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json floorBelow(const LevelRayCaster& caster, const glm::dvec3& pointMeters) {
  const std::optional<double> z = floorHeightBelow(caster, pointMeters, kFloorSearchMeters);
  return z ? nlohmann::json(*z) : nlohmann::json(nullptr);
}

int runLevelInfo(const LevelInfoOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const BspLevel level = readBspLevel(o.level, o.map);
  const double loadMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const LevelRayCaster caster(level.mesh);

  nlohmann::json spawns = nlohmann::json::array();
  for (const BspSpawnPoint& s : level.spawnPoints) {
    spawns.push_back({{"classname", s.classname},
                      {"origin", vec3Json(s.originMeters)},
                      {"angles_deg", vec3Json(s.anglesDegrees)},
                      {"floor_z", floorBelow(caster, s.originMeters)}});
  }
  nlohmann::json lights = nlohmann::json::array();
  for (const BspLight& l : level.lights) {
    lights.push_back({{"origin", vec3Json(l.originMeters)},
                      {"intensity", l.intensity},
                      {"color", vec3Json(l.color)}});
  }
  const BspFaceCounts& f = level.faces;
  const nlohmann::json report = {{"level", o.level},
                                 {"map", o.map},
                                 {"triangles", level.mesh.triangles.size()},
                                 {"sky_triangles", level.mesh.skyTriangles.size()},
                                 {"load_ms", loadMs},
                                 {"faces",
                                  {{"polygons", f.polygons},
                                   {"meshes", f.meshes},
                                   {"patches", f.patches},
                                   {"billboards", f.billboards},
                                   {"skipped_by_flags", f.skippedByFlags},
                                   {"sky", f.sky}}},
                                 {"spawn_points", spawns},
                                 {"lights", lights}};
  std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace

Verb addLevelInfoVerb(CLI::App& app) {
  auto o = std::make_shared<LevelInfoOptions>();
  CLI::App* verb = app.add_subcommand(
      "level-info", "Print a Quake 3 BSP level's figures, spawn points and lights as JSON");
  verb->group("");  // hidden from --help: a utility for scripts/corpus, not a product verb
  verb->add_option("level", o->level, ".bsp file, or .pk3 archive with --map")->required();
  verb->add_option("--map", o->map, "the .bsp inside the .pk3, e.g. maps/downer.bsp");
  return {verb, [o] { return runLevelInfo(*o); }};
}

}  // namespace probeproxy::cli
