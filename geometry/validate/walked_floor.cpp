// The floor, proxy-error and leak rules measure on the floor a player walks
// (docs/methods_and_measures.md, "Measures"), the one `survey` and `layout` measure on: the
// floor reached from the spawn points, or from the probes' capture points. Every upward surface
// under the sky would count roofs and the tops of walls no one stands on (on eggandbacon
// 236 m^2 of it, in no volume of a layout that covers all the floor a player reaches).

#include "geometry/validate/validation_rules.h"

namespace probeproxy {

WalkableFloor walkedFloor(const Scene& scene, const LevelRayCaster& level,
                          const ValidateOptions& options) {
  std::vector<glm::dvec3> seeds = options.seedPointsMeters;
  if (seeds.empty())
    for (const Probe& probe : scene.probes) seeds.push_back(probe.captureMeters);
  if (seeds.empty()) return {};
  WalkableFloorOptions floorOptions = options.walkedFloor;
  floorOptions.gridSpacingMeters = options.gridSpacingMeters;
  floorOptions.maxCells = options.gridPointBudget;
  return walkableFloor(level, seeds, floorOptions);
}

}  // namespace probeproxy
