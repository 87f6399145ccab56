#pragma once
// A level and its probes, as read from a `*.scene.json`. Everything is held in the world
// frame (Z up, metres); `fileUp` and `metersPerUnit` remember how the file spelled it so that
// writing it back gives the same file.

#include "core/scene/measure_settings.h"
#include "core/scene/probe.h"
#include "core/scene/world_frame.h"

#include <filesystem>
#include <vector>

namespace probeproxy {

struct LevelMeshRef {
  std::filesystem::path path;  // absolute, resolved against the scene file's folder
  std::filesystem::path pathAsWritten;
  UpAxis up = UpAxis::Z;       // the mesh file's own up axis
  bool upWasExplicit = false;  // written back only when the file said it
  // For a .pk3 (a zip of game data): the Quake 3 .bsp inside it, e.g. "maps/downer.bsp";
  // empty for every other mesh file.
  std::filesystem::path map;
};

struct Scene {
  std::filesystem::path file;  // where it was read from (absolute); empty if built in memory
  UpAxis fileUp = UpAxis::Z;
  double metersPerUnit = 1.0;
  std::vector<LevelMeshRef> level;
  std::vector<Probe> probes;
  MeasureSettings measuredWith;  // what a layout measured the scene's figures with
};

}  // namespace probeproxy
