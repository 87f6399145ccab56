#include "geometry/layout/grid_layout.h"

#include "geometry/layout/layout_candidates.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/survey/storeys.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace probeproxy {

namespace {

using Square = std::tuple<long, long, int>;  // row, column, storey

// Ordered by square and storey, so the probes come out in the same order every run.
std::map<Square, GridCellProbe> gridSquares(const WalkableFloor& floor,
                                            const std::vector<int>& storeys, double spacingMeters) {
  // Ordered by square and storey, so the probes come out in the same order every run.
  std::map<Square, GridCellProbe> squares;
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    const glm::dvec3 p = floor.cells[i].pointMeters;
    const long x = static_cast<long>(std::floor((p.x - floor.originMeters.x) / spacingMeters));
    const long y = static_cast<long>(std::floor((p.y - floor.originMeters.y) / spacingMeters));
    squares[{y, x, storeys[i]}].cells.push_back(i);
  }
  return squares;
}

std::vector<GridCellProbe> placeCaptures(const LevelRayCaster& level, const WalkableFloor& floor,
                                         std::map<Square, GridCellProbe> squares,
                                         double spacingMeters, double captureHeightMeters) {
  std::vector<GridCellProbe> probes;
  for (auto& [key, square] : squares) {
    const auto [y, x, storey] = key;
    const glm::dvec3 centre(floor.originMeters.x + (x + 0.5) * spacingMeters,
                            floor.originMeters.y + (y + 0.5) * spacingMeters, 0.0);
    // The floor cell nearest the centre whose capture point stands clear of every surface, else
    // the clearest of its cells; a square where every capture point touches a surface (a
    // sliver of floor under a beam) gets no probe: a scene may not hold one there.
    const ClearCapture clear = clearCaptureAbove(
        level, floor, nearestFirst(floor, square.cells, centre), captureHeightMeters);
    square.captureMeters = clear.captureMeters;
    if (clear.clearanceMeters < kMinCaptureClearanceMeters) continue;
    probes.push_back(std::move(square));
  }
  return probes;
}

}  // namespace

std::vector<GridCellProbe> gridLayout(const LevelRayCaster& level, const WalkableFloor& floor,
                                      double spacingMeters, double captureHeightMeters) {
  return placeCaptures(level, floor, gridSquares(floor, floorStoreys(floor), spacingMeters),
                       spacingMeters, captureHeightMeters);
}

std::vector<GridCellProbe> gridLayoutWithin(const LevelRayCaster& level, const WalkableFloor& floor,
                                            double spacingMeters, double captureHeightMeters,
                                            std::size_t maxProbes, double& spacingTaken) {
  spacingTaken = spacingMeters;
  if (maxProbes == 0) return gridLayout(level, floor, spacingTaken, captureHeightMeters);
  // From the floor's own cell size up: the finest grid within the budget.
  const std::vector<int> storeys = floorStoreys(floor);
  spacingTaken = floor.spacingMeters;
  auto squares = gridSquares(floor, storeys, spacingTaken);
  while (squares.size() > maxProbes) {
    spacingTaken *= 1.05;
    squares = gridSquares(floor, storeys, spacingTaken);
  }
  return placeCaptures(level, floor, std::move(squares), spacingTaken, captureHeightMeters);
}

}  // namespace probeproxy
