#pragma once
// The grid the floor, overlap and inner-range rules sample a box on: cell centres at
// ValidateOptions::gridSpacingMeters, coarsened so that no box holds more than about
// gridPointBudget points (a huge level). The layout samples the same grid where it must pass
// those rules (geometry/layout/overlap_trim.h).

#include "geometry/validate/validate_scene.h"

#include <glm/vec3.hpp>

namespace probeproxy {

struct ValidationGrid {
  glm::dvec3 loMeters{0.0};    // the box's low corner
  glm::dvec3 cellMeters{1.0};  // one cell's size per axis, <= the spacing asked, x the coarsening
  glm::ivec3 count{0};         // cells per axis, >= 1
  double cellCubicMeters() const { return cellMeters.x * cellMeters.y * cellMeters.z; }
  glm::dvec3 at(int i, int j, int k) const {
    return loMeters + (glm::dvec3(i, j, k) + 0.5) * cellMeters;
  }
};

ValidationGrid validationGrid(glm::dvec3 loMeters, glm::dvec3 hiMeters,
                              const ValidateOptions& options);

// x fastest, then y, then z: the order the rules name their first worst point in.
template <class F>
void forEachPoint(const ValidationGrid& grid, F&& f) {
  for (int k = 0; k < grid.count.z; ++k)
    for (int j = 0; j < grid.count.y; ++j)
      for (int i = 0; i < grid.count.x; ++i) f(grid.at(i, j, k));
}

}  // namespace probeproxy
