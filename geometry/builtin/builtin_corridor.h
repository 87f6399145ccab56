#pragma once
// The built-in level of `probeproxy demo`: the seed's corridor (Lagarde & Zanuttini 2012, the
// top-down corridor with three local cubemaps): 18 x 3 x 3 m, x in [-9, 9], y in [-1.5, 1.5],
// z in [0, 3], probes at x = -6, 0, 6 at 1.6 m, overlapping box influence volumes, and the
// artist box (the corridor's bounds) as each probe's authored proxy. The Blender suite's
// `corridor` level has the same geometry and probes.

#include "core/scene/scene.h"
#include "geometry/level/level_mesh.h"

namespace probeproxy {

struct BuiltinLevel {
  Scene scene;  // level[] names `meshFileName`, relative to where the scene is written
  LevelMesh level;
  std::string meshFileName;
};

BuiltinLevel builtinCorridor();

}  // namespace probeproxy
