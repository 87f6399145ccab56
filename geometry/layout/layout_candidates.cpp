#include "geometry/layout/layout_candidates.h"

#include "geometry/probe_proxies/build_scene_proxies.h"

#include <algorithm>
#include <cmath>

namespace probeproxy {

glm::dvec3 captureAbove(const LevelRayCaster& level, glm::dvec3 floorMeters, double heightMeters) {
  Ray up;
  up.originMeters = floorMeters + glm::dvec3(0.0, 0.0, 1e-3);
  up.direction = {0.0f, 0.0f, 1.0f};
  up.tMax = static_cast<float>(2.0 * heightMeters);
  const RayHit hit = level.firstHit(up);
  const double freeHeight = hit.hit() ? hit.t : 2.0 * heightMeters;
  return floorMeters + glm::dvec3(0.0, 0.0, std::min(heightMeters, 0.5 * freeHeight));
}

LayoutCandidates layoutCandidates(const LevelRayCaster& level, const WalkableFloor& floor,
                                  double spacingMeters, double captureHeightMeters,
                                  std::size_t maxCandidates) {
  // Every step-th column and row, offset by half a step so a room's first candidate stands off
  // its wall.
  int step = std::max(1, static_cast<int>(std::lround(spacingMeters / floor.spacingMeters)));
  const auto onGrid = [&](const FloorCell& cell) {
    return cell.column % step == step / 2 && cell.row % step == step / 2;
  };
  while (std::count_if(floor.cells.begin(), floor.cells.end(), onGrid) >
         static_cast<std::ptrdiff_t>(maxCandidates))
    ++step;
  LayoutCandidates candidates;
  candidates.spacingMeters = step * floor.spacingMeters;
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    const FloorCell& cell = floor.cells[i];
    if (!onGrid(cell)) continue;
    const glm::dvec3 capture = captureAbove(level, cell.pointMeters, captureHeightMeters);
    // A point in a wall's face or a thin prop would capture the level from behind it.
    if (nearestSurface(level, capture).distanceMeters < kLayoutCaptureClearanceMeters) continue;
    candidates.points.push_back({capture, i});
  }
  return candidates;
}

}  // namespace probeproxy
