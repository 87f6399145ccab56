#pragma once
// A Quake 3 BSP level (`IBSP` 46) read into the world frame: Z up as in the game, scaled
// from game units to metres (1/32 m per unit by default: a Quake 3 player is 56 units tall,
// about 1.75 m).
//
// What is kept: faces of type polygon, mesh and Bezier patch (tessellated), of every brush
// model (the world and the func_* entities, at their compiled positions), whose shader is
// solid world by its flags (bsp_surface_flags.h); sky faces go to LevelMesh::skyTriangles.
// Billboards (flares) are skipped. Triangles are grouped into one LevelPart per shader, named
// after it, in shader order. Windings are turned to the counter-clockwise-from-the-front
// convention the rest of the library uses (Quake 3 stores polygons and meshes clockwise).
//
// Bad or truncated files throw InputError(file, "lump N (name): ...") naming the lump that is
// wrong; every offset, length and index is checked before it is read.

#include "geometry/level/bsp/bsp_entities.h"
#include "geometry/level/level_mesh.h"

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace probeproxy {

inline constexpr double kQuakeMetersPerUnit = 1.0 / 32.0;

// Quake 3's player, which a BSP level's floor is walked for (ioquake3 code/game): STEPSIZE 18
// (bg_local.h), playerMins z -24 and playerMaxs z 32 (g_client.c: 56 units standing, the head
// room a floor needs) and DEFAULT_VIEWHEIGHT 26 above the origin (bg_public.h: eyes 50 units
// over the feet). Its walkable slope, MIN_WALK_NORMAL 0.7, is WalkableFloorOptions'. Games on
// the format differ (Nexuiz's physics26.cfg steps 34 units); the options override.
MeasureSettings quake3Player(double metersPerUnit);

struct BspLoadOptions {
  double metersPerUnit = kQuakeMetersPerUnit;
  // Quads per side of each 3x3 Bezier piece (two triangles each); 4 keeps a quarter-circle
  // arch of radius r within 2% of r.
  int patchSubdivisions = 4;
};

// What the faces were, for reports and tests.
struct BspFaceCounts {
  std::size_t polygons = 0;  // kept faces by type
  std::size_t meshes = 0;
  std::size_t patches = 0;
  std::size_t billboards = 0;      // skipped: a flare has no surface
  std::size_t skippedByFlags = 0;  // not solid world (nodraw, clip, trigger, water...)
  std::size_t sky = 0;             // recorded in skyTriangles
};

struct BspLevel {
  LevelMesh mesh;  // may have no triangles: the caller decides whether that is an error
  std::vector<BspEntity> entities;
  std::vector<BspSpawnPoint> spawnPoints;
  std::vector<BspLight> lights;
  BspFaceCounts faces;
};

// `bytes` is the whole .bsp; `file` names it in errors and in LevelPart::file.
BspLevel parseBspLevel(std::span<const std::byte> bytes, const std::filesystem::path& file,
                       const BspLoadOptions& options = {});

// A .bsp file, or with `mapInArchive` non-empty, the .bsp of that name inside a .pk3 (zip)
// `file`; errors then name "<file>:<mapInArchive>".
BspLevel readBspLevel(const std::filesystem::path& file,
                      const std::filesystem::path& mapInArchive = {},
                      const BspLoadOptions& options = {});

}  // namespace probeproxy
