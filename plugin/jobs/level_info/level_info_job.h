#pragma once
// `level-info` (a utility for scripts/corpus, hidden from --help): a Quake 3 BSP level loaded
// as `build` loads it, and what a scene writer needs and the corpus table reports: triangle
// counts, load time, face counts, every player spawn point and light with the floor under it
// (the first level surface straight below, within 64 m; null if none).

#include <filesystem>
#include <string>

namespace probeproxy::jobs {

struct LevelInfoJobOptions {
  std::filesystem::path level;  // .bsp, or .pk3 with `map`
  std::string map;              // the .bsp inside the .pk3, e.g. maps/downer.bsp
};

// The report as JSON: {"level", "map", "triangles", "sky_triangles", "load_ms", "faces":
// {...}, "spawn_points": [{"classname", "origin", "angles_deg", "floor_z"}], "lights": [...]}.
std::string runLevelInfoJob(const LevelInfoJobOptions& options);

}  // namespace probeproxy::jobs
