#pragma once
// The walkable floor's graph (walkable_floor.h): the floor layers under every column of a
// regular XY grid and the steps a player can take between neighbouring ones. Building it is all
// the ray casting; a flood fill in it is cheap. `walkableFloor` builds one and fills it once;
// `layout` builds one for the whole level and fills it for each of its thousands of candidate
// probes (the floor a probe serves, reflection_samples.h) instead of casting every column again.

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

struct FloorLayer {  // one floor surface under a grid column
  double zMeters = 0.0;
  glm::dvec3 normal{0, 0, 1};  // unit, facing up
};

struct FloorGraph {
  glm::dvec2 originMeters{0.0};  // world x, y of the grid's corner (column 0, row 0)
  double spacingMeters = 0.0;
  int columns = 0, rows = 0;
  double stepHeightMeters = 0.0;  // what the graph was built with (a seed's reach above a floor)
  // Column i = row * columns + column holds layers[firstLayer[i] .. firstLayer[i + 1]), lowest
  // first; layer a's neighbours are neighbours[firstNeighbour[a] .. firstNeighbour[a + 1]).
  std::vector<std::size_t> firstLayer;
  std::vector<FloorLayer> layers;
  std::vector<std::uint32_t> columnOfLayer;  // the column index i of each layer
  std::vector<std::size_t> firstNeighbour;
  std::vector<std::uint32_t> neighbours;

  glm::dvec2 centre(int column, int row) const {
    return originMeters + spacingMeters * glm::dvec2(column + 0.5, row + 0.5);
  }
};

// Every column of options' region (clipped to the level) on a grid of options' spacing
// (coarsened past maxCells), with its floor layers and their steps. Parallel over columns,
// the same graph whatever the thread count.
FloorGraph buildFloorGraph(const LevelRayCaster& level, const WalkableFloorOptions& options);

// The floor reachable from `seedsMeters` without leaving the columns that touch options'
// region (a graph built for that region: all of them). The graph's own options hold for the
// rest. A seed starts as in walkableFloor.
WalkableFloor reachableFloor(const FloorGraph& graph, std::span<const glm::dvec3> seedsMeters,
                             glm::dvec2 regionMinMeters = glm::dvec2(-1e300),
                             glm::dvec2 regionMaxMeters = glm::dvec2(1e300));

}  // namespace probeproxy
