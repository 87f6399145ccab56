#include "geometry/validate/validation_rules.h"

#include <glm/common.hpp>

#include <cmath>

namespace probeproxy {

namespace {

// A floor faces up within about 45 degrees (ramps and stairs included). Levels are wound to
// face into the playable space, so the top of a ceiling slab faces down and is skipped.
constexpr float kUpwardCosine = 0.7f;
constexpr int kMaxStoreys = 32;  // surfaces one column passes through before it gives up
constexpr float kStepMeters = 1e-3f;

}  // namespace

std::vector<FloorPoint> walkableFloor(const LevelRayCaster& level, const ValidateOptions& options) {
  const glm::dvec3 lo = level.boundsMinMeters(), hi = level.boundsMaxMeters();
  const glm::dvec2 size(hi.x - lo.x, hi.y - lo.y);
  // Coarsen the grid on huge levels so the column count stays within the budget.
  double spacing = options.gridSpacingMeters;
  const double columns = (size.x / spacing + 1.0) * (size.y / spacing + 1.0);
  const double budget = static_cast<double>(options.gridPointBudget);
  if (columns > budget) spacing *= std::sqrt(columns / budget);
  const int nx = std::max(1, static_cast<int>(std::ceil(size.x / spacing)));
  const int ny = std::max(1, static_cast<int>(std::ceil(size.y / spacing)));
  const double cellArea = (size.x / nx) * (size.y / ny);
  const double topZ = hi.z + 1.0;

  std::vector<FloorPoint> floor;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      // Cell centres, so a column never runs along a wall.
      Ray down;
      down.originMeters = {lo.x + (i + 0.5) * size.x / nx, lo.y + (j + 0.5) * size.y / ny, topZ};
      down.direction = {0.0f, 0.0f, -1.0f};
      for (int storey = 0; storey < kMaxStoreys; ++storey) {
        const RayHit hit = level.firstHit(down);
        if (!hit.hit()) break;
        const glm::dvec3 at = down.originMeters + glm::dvec3(0.0, 0.0, -hit.t);
        if (hit.geometricNormal.z >= kUpwardCosine) {
          Ray up;
          up.originMeters = at + glm::dvec3(0.0, 0.0, kStepMeters);
          up.direction = {0.0f, 0.0f, 1.0f};
          up.tMax = static_cast<float>(options.headroomMeters);
          if (!level.firstHit(up).hit()) floor.push_back({at, cellArea});
        }
        down.originMeters = at;
        down.tMin = kStepMeters;
      }
    }
  }
  return floor;
}

}  // namespace probeproxy
