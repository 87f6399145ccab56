#include "geometry/validate/validation_grid.h"

#include <glm/common.hpp>

#include <cmath>

namespace probeproxy {

ValidationGrid validationGrid(glm::dvec3 lo, glm::dvec3 hi, const ValidateOptions& options) {
  const glm::dvec3 size = glm::max(hi - lo, glm::dvec3(0.0));
  double spacing = options.gridSpacingMeters;
  const glm::dvec3 n = size / spacing + 1.0;
  const double points = n.x * n.y * n.z;
  const double budget = static_cast<double>(options.gridPointBudget);
  if (points > budget) spacing *= std::cbrt(points / budget);
  ValidationGrid grid;
  grid.loMeters = lo;
  grid.count = glm::max(glm::ivec3(glm::ceil(size / spacing)), glm::ivec3(1));
  grid.cellMeters = size / glm::dvec3(grid.count);
  return grid;
}

}  // namespace probeproxy
