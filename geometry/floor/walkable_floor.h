#pragma once
// The walkable floor (docs/methods_and_measures.md, "Measures"): upward-facing level surfaces a
// player can reach from seed points (spawn points, or the probes' capture points), by a flood fill
// over a regular XY grid of floor cells with a step height and a head clearance. The tops of
// pillars, the outside of the map and sealed voids are not reached, so they do not count. World
// frame (Z up), metres. Deterministic: the same level, seeds and options give the same floor,
// whatever the thread count.

#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

struct WalkableFloorOptions {
  double gridSpacingMeters = 0.25;   // side of a floor cell
  double stepHeightMeters = 0.45;    // largest height change between neighbouring cells
  double headClearanceMeters = 1.8;  // free height a floor cell needs above it
  // Height above the higher of two neighbouring cells at which a ray between them must be free
  // (no wall between them); above the step height, so a stair's riser is not a wall.
  double kneeHeightMeters = 0.6;
  double upwardCosine = 0.7;         // |normal.z| at least this (about 45 degrees: ramps, stairs)
  std::size_t maxCells = 4'000'000;  // grid columns; the spacing is coarsened to stay within it
  // Only this part of the plan (world x, y) is searched, clipped to the level's bounds: the
  // floor a probe serves, reachable within its influence. Unbounded by default.
  glm::dvec2 regionMinMeters{-1e300}, regionMaxMeters{1e300};
  void check() const;  // InputError on a value out of range
};

// The wall test between two cells runs above a step: a taller step than the knee (Nexuiz's
// 1.06 m) lifts the knee over it, below the head.
void raiseKneeOverStep(WalkableFloorOptions& options);

struct FloorCell {
  int column = 0, row = 0;        // grid indices (x, y)
  glm::dvec3 pointMeters{0.0};    // on the surface, at the cell's centre column
  glm::dvec3 normal{0, 0, 1};     // unit, facing up
  double areaSquareMeters = 0.0;  // of the surface in the cell: plan area / normal.z
};

struct WalkableFloor {
  glm::dvec2 originMeters{0.0};  // world x, y of the grid's corner (column 0, row 0)
  double spacingMeters = 0.0;
  int columns = 0, rows = 0;
  std::vector<FloorCell> cells;    // the reachable cells, by row, column, then height
  std::size_t candidateCells = 0;  // floor cells with head room, reachable or not
  std::size_t seedsOnFloor = 0;    // seed points that found a floor cell under them

  double areaSquareMeters() const;
  // Whether a point lies on a reachable cell: in its column, on a cell within
  // `heightToleranceMeters` of the point's height.
  bool reaches(glm::dvec3 pointMeters, double heightToleranceMeters) const;
};

// The floor reachable from `seedsMeters`. A seed starts at the highest floor cell of its grid
// column within a step above it (else the nearest such cell of the 8 columns around it); a seed
// with none starts nothing.
WalkableFloor walkableFloor(const LevelRayCaster& level, std::span<const glm::dvec3> seedsMeters,
                            const WalkableFloorOptions& options = {});

}  // namespace probeproxy
