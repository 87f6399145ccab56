#include "geometry/floor/walkable_floor.h"

#include "geometry/floor/floor_graph.h"

#include "core/errors/option_checks.h"

#include "core/errors/input_error.h"

#include <algorithm>
#include <cmath>

namespace probeproxy {

void WalkableFloorOptions::check() const {
  requireInRange("grid", gridSpacingMeters, 0.01, 10.0);
  requireInRange("step_height", stepHeightMeters, 0.0, 5.0);
  requireInRange("head_clearance", headClearanceMeters, 1e-3, 10.0);
  if (!(stepHeightMeters < headClearanceMeters))
    throw InputError("option step_height", "must be below the head clearance");
  // The wall test between neighbours runs at knee height: over a step, under a head.
  if (!(kneeHeightMeters > stepHeightMeters && kneeHeightMeters < headClearanceMeters))
    throw InputError("option knee_height_m",
                     "must lie above the step height and below the head clearance");
  requireInRange("upward_cosine", upwardCosine, 1e-9, 1.0);
  requireInRange<std::size_t>("max_cells", maxCells, 1, std::size_t(1) << 40);
}

void raiseKneeOverStep(WalkableFloorOptions& o) {
  if (o.kneeHeightMeters > o.stepHeightMeters) return;
  o.kneeHeightMeters =
      std::min(o.stepHeightMeters + 0.15, 0.5 * (o.stepHeightMeters + o.headClearanceMeters));
}

bool WalkableFloor::reaches(glm::dvec3 p, double heightToleranceMeters) const {
  if (spacingMeters <= 0.0) return false;
  const int column = static_cast<int>(std::floor((p.x - originMeters.x) / spacingMeters));
  const int row = static_cast<int>(std::floor((p.y - originMeters.y) / spacingMeters));
  // Cells are sorted by row, then column, then height.
  const auto first = std::lower_bound(
      cells.begin(), cells.end(), std::make_pair(row, column),
      [](const FloorCell& c, auto key) { return std::make_pair(c.row, c.column) < key; });
  for (auto it = first; it != cells.end() && it->row == row && it->column == column; ++it) {
    if (std::abs(it->pointMeters.z - p.z) <= heightToleranceMeters) return true;
  }
  return false;
}

double WalkableFloor::areaSquareMeters() const {
  double area = 0.0;
  for (const FloorCell& c : cells) area += c.areaSquareMeters;
  return area;
}

WalkableFloor walkableFloor(const LevelRayCaster& level, std::span<const glm::dvec3> seedsMeters,
                            const WalkableFloorOptions& o) {
  return reachableFloor(buildFloorGraph(level, o), seedsMeters);
}

}  // namespace probeproxy
