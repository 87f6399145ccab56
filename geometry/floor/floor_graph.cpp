#include "geometry/floor/floor_graph.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

constexpr int kMaxLayersPerColumn = 64;      // surfaces one column passes through before it stops
constexpr double kOffsetMeters = 1e-3;       // off a surface, so a ray does not hit it again
constexpr double kSameSurfaceMeters = 0.01;  // duplicate triangles: one floor, not two

void placeGrid(const LevelRayCaster& level, const WalkableFloorOptions& o, FloorGraph& g) {
  glm::dvec3 lo = level.boundsMinMeters(), hi = level.boundsMaxMeters();
  lo.x = std::max(lo.x, o.regionMinMeters.x), lo.y = std::max(lo.y, o.regionMinMeters.y);
  hi.x = std::min(hi.x, o.regionMaxMeters.x), hi.y = std::min(hi.y, o.regionMaxMeters.y);
  hi.x = std::max(hi.x, lo.x), hi.y = std::max(hi.y, lo.y);  // a region off the level: one cell
  g.originMeters = glm::dvec2(lo);
  g.spacingMeters = o.gridSpacingMeters;
  const double area = (hi.x - lo.x) * (hi.y - lo.y);
  // Coarsen on huge levels so the column count stays within the budget.
  if (area / (g.spacingMeters * g.spacingMeters) > static_cast<double>(o.maxCells))
    g.spacingMeters = std::sqrt(area / static_cast<double>(o.maxCells));
  g.columns = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / g.spacingMeters)));
  g.rows = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / g.spacingMeters)));
}

// Every upward-facing surface under the column with head room over it, lowest first. Either
// winding counts (real levels are not consistently wound); the flood fill, not the normal,
// tells a floor from the top of the map's shell. Where the level's faces are one-sided (a
// BSP), the back of a ceiling is not a floor: it lies in the void over the map, and a flood
// fill that steps onto it there (final_rage: 256 m^2 over two ceilings, where layout placed
// probes) walks where no player stands.
std::vector<FloorLayer> columnLayers(const LevelRayCaster& level, glm::dvec2 xy, double topZ,
                                     const WalkableFloorOptions& o) {
  std::vector<FloorLayer> layers;
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
    if (std::abs(n.z) < o.upwardCosine || (level.facesOneSided() && n.z < 0.0)) continue;
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

// The columns whose squares touch [lo, hi] along one axis, clamped to the grid.
std::pair<int, int> columnRange(double lo, double hi, double origin, double spacing, int count) {
  const double first = std::clamp(std::floor((lo - origin) / spacing), 0.0, double(count - 1));
  const double last =
      std::clamp(std::ceil((hi - origin) / spacing) - 1.0, first, double(count - 1));
  return {static_cast<int>(first), static_cast<int>(last)};
}

struct Window {
  int c0, c1, r0, r1;  // inclusive
  bool holds(int c, int r) const { return c >= c0 && c <= c1 && r >= r0 && r <= r1; }
};

// The cell a seed starts at: in its own column the highest floor within a step above it,
// else the nearest such floor among the 8 columns around it.
std::ptrdiff_t seedLayer(const FloorGraph& g, const Window& w, glm::dvec3 seed) {
  const int c0 = static_cast<int>(std::floor((seed.x - g.originMeters.x) / g.spacingMeters));
  const int r0 = static_cast<int>(std::floor((seed.y - g.originMeters.y) / g.spacingMeters));
  auto highestBelow = [&](int c, int r) -> std::ptrdiff_t {
    if (!w.holds(c, r)) return -1;
    const std::size_t col = static_cast<std::size_t>(r) * g.columns + c;
    std::ptrdiff_t best = -1;
    for (std::size_t l = g.firstLayer[col]; l < g.firstLayer[col + 1]; ++l)
      if (g.layers[l].zMeters <= seed.z + g.stepHeightMeters) best = static_cast<std::ptrdiff_t>(l);
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
      const double distance = std::hypot(d.x, d.y, seed.z - g.layers[l].zMeters);
      if (best < 0 || distance < bestDistance) best = l, bestDistance = distance;
    }
  }
  return best;
}

}  // namespace

FloorGraph buildFloorGraph(const LevelRayCaster& level, const WalkableFloorOptions& o) {
  o.check();
  FloorGraph g;
  placeGrid(level, o, g);
  g.stepHeightMeters = o.stepHeightMeters;
  const std::size_t columnCount = static_cast<std::size_t>(g.rows) * g.columns;
  const double topZ = level.boundsMaxMeters().z + 1.0;

  // 1. The floor layers of every column (independent columns: parallel, same result).
  std::vector<std::vector<FloorLayer>> perColumn(columnCount);
  tbb::parallel_for(std::size_t{0}, columnCount, [&](std::size_t i) {
    const int c = static_cast<int>(i % g.columns), r = static_cast<int>(i / g.columns);
    perColumn[i] = columnLayers(level, g.centre(c, r), topZ, o);
  });
  g.firstLayer.assign(columnCount + 1, 0);
  for (std::size_t i = 0; i < columnCount; ++i)
    g.firstLayer[i + 1] = g.firstLayer[i] + perColumn[i].size();
  g.layers.reserve(g.firstLayer.back());
  g.columnOfLayer.reserve(g.firstLayer.back());
  for (std::size_t i = 0; i < columnCount; ++i) {
    g.layers.insert(g.layers.end(), perColumn[i].begin(), perColumn[i].end());
    g.columnOfLayer.insert(g.columnOfLayer.end(), perColumn[i].size(), std::uint32_t(i));
  }
  perColumn = {};

  // 2. Steps to the +x and +y neighbours, found per column, then both ways per layer.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> steps(columnCount);
  tbb::parallel_for(std::size_t{0}, columnCount, [&](std::size_t i) {
    const int c = static_cast<int>(i % g.columns), r = static_cast<int>(i / g.columns);
    const glm::dvec2 here = g.centre(c, r);
    for (const auto& [dc, dr] : {std::pair{1, 0}, std::pair{0, 1}}) {
      if (c + dc >= g.columns || r + dr >= g.rows) continue;
      const std::size_t j = static_cast<std::size_t>(r + dr) * g.columns + (c + dc);
      const glm::dvec2 there = g.centre(c + dc, r + dr);
      for (std::size_t a = g.firstLayer[i]; a < g.firstLayer[i + 1]; ++a)
        for (std::size_t b = g.firstLayer[j]; b < g.firstLayer[j + 1]; ++b)
          if (connected(level, here, g.layers[a].zMeters, there, g.layers[b].zMeters, o))
            steps[i].emplace_back(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b));
    }
  });
  g.firstNeighbour.assign(g.layers.size() + 1, 0);
  for (const auto& column : steps)
    for (const auto& [a, b] : column) ++g.firstNeighbour[a + 1], ++g.firstNeighbour[b + 1];
  for (std::size_t a = 0; a < g.layers.size(); ++a) g.firstNeighbour[a + 1] += g.firstNeighbour[a];
  g.neighbours.resize(g.firstNeighbour.back());
  std::vector<std::size_t> next(g.firstNeighbour.begin(), g.firstNeighbour.end() - 1);
  for (const auto& column : steps) {
    for (const auto& [a, b] : column) {
      g.neighbours[next[a]++] = b;
      g.neighbours[next[b]++] = a;
    }
  }
  return g;
}

WalkableFloor reachableFloor(const FloorGraph& g, std::span<const glm::dvec3> seedsMeters,
                             glm::dvec2 regionMin, glm::dvec2 regionMax) {
  const auto [c0, c1] =
      columnRange(regionMin.x, regionMax.x, g.originMeters.x, g.spacingMeters, g.columns);
  const auto [r0, r1] =
      columnRange(regionMin.y, regionMax.y, g.originMeters.y, g.spacingMeters, g.rows);
  const Window window{c0, c1, r0, r1};
  const auto inWindow = [&](std::size_t layer) {
    const std::uint32_t i = g.columnOfLayer[layer];
    return window.holds(static_cast<int>(i % g.columns), static_cast<int>(i / g.columns));
  };

  WalkableFloor floor;
  floor.originMeters = g.originMeters;
  floor.spacingMeters = g.spacingMeters;
  floor.columns = g.columns;
  floor.rows = g.rows;
  // The reachable set does not depend on the visiting order.
  std::vector<char> reached(g.layers.size(), 0);
  std::vector<std::size_t> found;  // every reached layer, in the order reached
  for (const glm::dvec3& seed : seedsMeters) {
    const std::ptrdiff_t start = seedLayer(g, window, seed);
    if (start < 0) continue;
    ++floor.seedsOnFloor;
    if (!reached[start]) found.push_back(static_cast<std::size_t>(start));
    reached[start] = 1;
  }
  for (std::size_t next = 0; next < found.size(); ++next) {
    const std::size_t a = found[next];
    for (std::size_t k = g.firstNeighbour[a]; k < g.firstNeighbour[a + 1]; ++k) {
      const std::size_t b = g.neighbours[k];
      if (reached[b] || !inWindow(b)) continue;
      found.push_back(b);
      reached[b] = 1;
    }
  }

  for (int r = r0; r <= r1; ++r) {
    const std::size_t rowStart = static_cast<std::size_t>(r) * g.columns;
    floor.candidateCells += g.firstLayer[rowStart + c1 + 1] - g.firstLayer[rowStart + c0];
  }
  // Layers are stored by row, column, then height: in index order the cells come out so.
  std::sort(found.begin(), found.end());
  const double planArea = g.spacingMeters * g.spacingMeters;
  floor.cells.reserve(found.size());
  for (const std::size_t l : found) {
    const std::uint32_t i = g.columnOfLayer[l];
    const int c = static_cast<int>(i % g.columns), r = static_cast<int>(i / g.columns);
    const glm::dvec2 xy = g.centre(c, r);
    const FloorLayer& layer = g.layers[l];
    floor.cells.push_back(
        {c, r, {xy.x, xy.y, layer.zMeters}, layer.normal, planArea / layer.normal.z});
  }
  return floor;
}

}  // namespace probeproxy
