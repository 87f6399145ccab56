#include "geometry/floor/walkable_floor.h"

#include "core/errors/option_checks.h"

#include "core/errors/input_error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>

namespace probeproxy {

namespace {

constexpr int kMaxLayersPerColumn = 64;      // surfaces one column passes through before it stops
constexpr double kOffsetMeters = 1e-3;       // off a surface, so a ray does not hit it again
constexpr double kSameSurfaceMeters = 0.01;  // duplicate triangles: one floor, not two

struct Layer {  // one floor surface under a grid column
  double zMeters = 0.0;
  glm::dvec3 normal{0, 0, 1};
};

struct Grid {
  glm::dvec2 origin{0.0};
  double spacing = 0.0;
  int columns = 0, rows = 0;

  glm::dvec2 centre(int column, int row) const {
    return origin + spacing * glm::dvec2(column + 0.5, row + 0.5);
  }
  std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * columns + column;
  }
};

Grid makeGrid(const LevelRayCaster& level, const WalkableFloorOptions& o) {
  glm::dvec3 lo = level.boundsMinMeters(), hi = level.boundsMaxMeters();
  lo.x = std::max(lo.x, o.regionMinMeters.x), lo.y = std::max(lo.y, o.regionMinMeters.y);
  hi.x = std::min(hi.x, o.regionMaxMeters.x), hi.y = std::min(hi.y, o.regionMaxMeters.y);
  hi.x = std::max(hi.x, lo.x), hi.y = std::max(hi.y, lo.y);  // a region off the level: one cell
  Grid g;
  g.origin = glm::dvec2(lo);
  g.spacing = o.gridSpacingMeters;
  const double area = (hi.x - lo.x) * (hi.y - lo.y);
  // Coarsen on huge levels so the column count stays within the budget.
  if (area / (g.spacing * g.spacing) > static_cast<double>(o.maxCells))
    g.spacing = std::sqrt(area / static_cast<double>(o.maxCells));
  g.columns = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / g.spacing)));
  g.rows = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / g.spacing)));
  return g;
}

// Every upward-facing surface under the column with head room over it, lowest first. Either
// winding counts (real levels are not consistently wound); the flood fill, not the normal,
// tells a floor from the top of the map's shell.
std::vector<Layer> columnLayers(const LevelRayCaster& level, glm::dvec2 xy, double topZ,
                                const WalkableFloorOptions& o) {
  std::vector<Layer> layers;
  Ray down;
  down.originMeters = {xy.x, xy.y, topZ};
  down.direction = {0.0f, 0.0f, -1.0f};
  for (int k = 0; k < kMaxLayersPerColumn; ++k) {
    const RayHit hit = level.firstHit(down);
    if (!hit.hit()) break;
    const glm::dvec3 at = down.originMeters - glm::dvec3(0.0, 0.0, hit.t);
    down.originMeters = at;
    down.tMin = static_cast<float>(kOffsetMeters);
    const glm::dvec3 n(hit.geometricNormal);
    if (std::abs(n.z) < o.upwardCosine) continue;
    if (!layers.empty() && layers.back().zMeters - at.z < kSameSurfaceMeters) continue;
    Ray up;
    up.originMeters = at + glm::dvec3(0.0, 0.0, kOffsetMeters);
    up.direction = {0.0f, 0.0f, 1.0f};
    up.tMax = static_cast<float>(o.headClearanceMeters);
    if (level.firstHit(up).hit()) continue;
    layers.push_back({at.z, n.z < 0.0 ? -n : n});
  }
  std::reverse(layers.begin(), layers.end());
  return layers;
}

// Whether a player can walk from one cell to its neighbour: the height changes by at most a
// step and a ray at knee height between the two columns meets no wall.
bool connected(const LevelRayCaster& level, glm::dvec2 from, double zFrom, glm::dvec2 to,
               double zTo, const WalkableFloorOptions& o) {
  if (std::abs(zTo - zFrom) > o.stepHeightMeters) return false;
  Ray knee;
  knee.originMeters = {from.x, from.y, std::max(zFrom, zTo) + o.kneeHeightMeters};
  knee.direction =
      glm::vec3(static_cast<float>(to.x - from.x), static_cast<float>(to.y - from.y), 0.0f);
  knee.tMax = 1.0f;
  return !level.firstHit(knee).hit();
}

// The cell a seed starts at: in its own column the highest floor within a step above it,
// else the nearest such floor among the 8 columns around it.
std::ptrdiff_t seedCell(const Grid& g, const std::vector<std::size_t>& firstLayer,
                        const std::vector<Layer>& layers, glm::dvec3 seed,
                        const WalkableFloorOptions& o) {
  const int c0 = static_cast<int>(std::floor((seed.x - g.origin.x) / g.spacing));
  const int r0 = static_cast<int>(std::floor((seed.y - g.origin.y) / g.spacing));
  auto highestBelow = [&](int c, int r) -> std::ptrdiff_t {
    if (c < 0 || r < 0 || c >= g.columns || r >= g.rows) return -1;
    const std::size_t col = g.index(c, r);
    std::ptrdiff_t best = -1;
    for (std::size_t l = firstLayer[col]; l < firstLayer[col + 1]; ++l)
      if (layers[l].zMeters <= seed.z + o.stepHeightMeters) best = static_cast<std::ptrdiff_t>(l);
    return best;
  };
  if (const std::ptrdiff_t own = highestBelow(c0, r0); own >= 0) return own;
  std::ptrdiff_t best = -1;
  double bestDistance = 0.0;
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const std::ptrdiff_t l = highestBelow(c0 + dc, r0 + dr);
      if (l < 0) continue;
      const glm::dvec2 d = g.centre(c0 + dc, r0 + dr) - glm::dvec2(seed);
      const double distance = std::hypot(d.x, d.y, seed.z - layers[l].zMeters);
      if (best < 0 || distance < bestDistance) best = l, bestDistance = distance;
    }
  }
  return best;
}

}  // namespace

void WalkableFloorOptions::check() const {
  requireInRange("grid", gridSpacingMeters, 0.01, 10.0);
  requireInRange("step_height", stepHeightMeters, 0.0, 5.0);
  requireInRange("head_clearance", headClearanceMeters, 1e-3, 10.0);
  // The wall test between neighbours runs at knee height: over a step, under a head.
  if (!(kneeHeightMeters > stepHeightMeters && kneeHeightMeters < headClearanceMeters))
    throw InputError("option knee_height_m",
                     "must lie above the step height and below the head clearance");
  requireInRange("upward_cosine", upwardCosine, 1e-9, 1.0);
  requireInRange<std::size_t>("max_cells", maxCells, 1, std::size_t(1) << 40);
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
  o.check();
  const Grid g = makeGrid(level, o);
  const std::size_t columnCount = g.index(0, g.rows);
  const double topZ = level.boundsMaxMeters().z + 1.0;

  // 1. The floor layers of every column (independent columns: parallel, same result).
  std::vector<std::vector<Layer>> perColumn(columnCount);
  tbb::parallel_for(std::size_t{0}, columnCount, [&](std::size_t i) {
    const int c = static_cast<int>(i % g.columns), r = static_cast<int>(i / g.columns);
    perColumn[i] = columnLayers(level, g.centre(c, r), topZ, o);
  });
  std::vector<std::size_t> firstLayer(columnCount + 1, 0);
  for (std::size_t i = 0; i < columnCount; ++i)
    firstLayer[i + 1] = firstLayer[i] + perColumn[i].size();
  std::vector<Layer> layers;
  layers.reserve(firstLayer.back());
  for (auto& column : perColumn) layers.insert(layers.end(), column.begin(), column.end());
  perColumn = {};

  // 2. Edges to the +x and +y neighbours, found per column, kept as lists per layer.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> edges(columnCount);
  tbb::parallel_for(std::size_t{0}, columnCount, [&](std::size_t i) {
    const int c = static_cast<int>(i % g.columns), r = static_cast<int>(i / g.columns);
    const glm::dvec2 here = g.centre(c, r);
    for (const auto& [dc, dr] : {std::pair{1, 0}, std::pair{0, 1}}) {
      if (c + dc >= g.columns || r + dr >= g.rows) continue;
      const std::size_t j = g.index(c + dc, r + dr);
      const glm::dvec2 there = g.centre(c + dc, r + dr);
      for (std::size_t a = firstLayer[i]; a < firstLayer[i + 1]; ++a)
        for (std::size_t b = firstLayer[j]; b < firstLayer[j + 1]; ++b)
          if (connected(level, here, layers[a].zMeters, there, layers[b].zMeters, o))
            edges[i].emplace_back(a, b);
    }
  });
  std::vector<std::vector<std::size_t>> neighbours(layers.size());
  for (const auto& column : edges) {
    for (const auto& [a, b] : column) {
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  }

  // 3. Flood fill from the seeds. The reachable set does not depend on the visiting order.
  WalkableFloor floor;
  floor.originMeters = g.origin;
  floor.spacingMeters = g.spacing;
  floor.columns = g.columns;
  floor.rows = g.rows;
  floor.candidateCells = layers.size();
  std::vector<char> reached(layers.size(), 0);
  std::deque<std::size_t> queue;
  for (const glm::dvec3& seed : seedsMeters) {
    const std::ptrdiff_t start = seedCell(g, firstLayer, layers, seed, o);
    if (start < 0) continue;
    ++floor.seedsOnFloor;
    if (!reached[start]) queue.push_back(static_cast<std::size_t>(start));
    reached[start] = 1;
  }
  while (!queue.empty()) {
    const std::size_t a = queue.front();
    queue.pop_front();
    for (const std::size_t b : neighbours[a]) {
      if (!reached[b]) queue.push_back(b);
      reached[b] = 1;
    }
  }

  // Layers are stored by row, column, then height: the cells come out in that order.
  const double planArea = g.spacing * g.spacing;
  for (std::size_t i = 0; i < columnCount; ++i) {
    const int c = static_cast<int>(i % g.columns), r = static_cast<int>(i / g.columns);
    for (std::size_t l = firstLayer[i]; l < firstLayer[i + 1]; ++l) {
      if (!reached[l]) continue;
      const glm::dvec2 xy = g.centre(c, r);
      floor.cells.push_back(
          {c, r, {xy.x, xy.y, layers[l].zMeters}, layers[l].normal, planArea / layers[l].normal.z});
    }
  }
  return floor;
}

}  // namespace probeproxy
