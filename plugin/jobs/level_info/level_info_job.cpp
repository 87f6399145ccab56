#include "plugin/jobs/level_info/level_info_job.h"

#include "geometry/level/bsp/bsp_level.h"
#include "geometry/raycast/floor_below.h"
#include "geometry/raycast/level_ray_caster.h"

#include <nlohmann/json.hpp>

#include <chrono>

namespace probeproxy::jobs {

namespace {

constexpr float kFloorSearchMeters = 64.0f;

nlohmann::json vec3Json(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json floorBelow(const LevelRayCaster& caster, const glm::dvec3& pointMeters) {
  const std::optional<double> z = floorHeightBelow(caster, pointMeters, kFloorSearchMeters);
  return z ? nlohmann::json(*z) : nlohmann::json(nullptr);
}

}  // namespace

std::string runLevelInfoJob(const LevelInfoJobOptions& o) {
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
  const nlohmann::json report = {{"level", o.level.string()},
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
  return report.dump(2) + "\n";
}

}  // namespace probeproxy::jobs
