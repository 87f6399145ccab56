#include "geometry/validate/overlap_points.h"

#include "geometry/validate/camera_space.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace probeproxy {

namespace {

// Rounding in a rotation's bounds must not drop a cell the exact test would count.
constexpr double kBoundsSlackMeters = 1e-6;

// The cells whose centres a volume's axis-aligned bounds hold, per axis [first, last).
struct CellRange {
  glm::ivec3 first{0}, last{0};
};

CellRange cellsWithin(const ValidationGrid& grid, glm::dvec3 lo, glm::dvec3 hi) {
  const glm::dvec3 from = (lo - grid.loMeters) / grid.cellMeters - 0.5;
  const glm::dvec3 to = (hi - grid.loMeters) / grid.cellMeters - 0.5;
  return {glm::clamp(glm::ivec3(glm::ceil(from)), glm::ivec3(0), grid.count),
          glm::clamp(glm::ivec3(glm::floor(to)) + 1, glm::ivec3(0), grid.count)};
}

}  // namespace

OverlapPoints overlapsOverLimit(std::span<const InfluenceVolume> volumes,
                                const LevelRayCaster& level, const WalkableFloor& walked,
                                const ValidateOptions& options) {
  OverlapPoints out;
  if (static_cast<int>(volumes.size()) <= options.maxOverlap) return out;
  glm::dvec3 lo, hi;
  influenceBounds(volumes, lo, hi);
  out.grid = validationGrid(lo, hi, options);
  const ValidationGrid& grid = out.grid;
  // Counting bounds first: only cells more bounds than the limit hold need the exact test
  // against every volume (a few per cent of a level's).
  const auto index = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * grid.count.y + j) * grid.count.x + i;
  };
  std::vector<std::uint16_t> bounds(static_cast<std::size_t>(grid.count.x) * grid.count.y *
                                    grid.count.z);
  for (const InfluenceVolume& v : volumes) {
    glm::dvec3 vlo, vhi;
    influenceBounds(v, vlo, vhi);
    const CellRange r = cellsWithin(grid, vlo - kBoundsSlackMeters, vhi + kBoundsSlackMeters);
    for (int k = r.first.z; k < r.last.z; ++k)
      for (int j = r.first.y; j < r.last.y; ++j)
        for (int i = r.first.x; i < r.last.x; ++i) ++bounds[index(i, j, k)];
  }
  std::vector<OverlapPoint> over;
  for (int k = 0; k < grid.count.z; ++k) {
    for (int j = 0; j < grid.count.y; ++j) {
      for (int i = 0; i < grid.count.x; ++i) {
        if (bounds[index(i, j, k)] <= options.maxOverlap) continue;
        OverlapPoint p{grid.at(i, j, k), {}};
        bool inner = false;
        for (std::size_t v = 0; v < volumes.size() && !inner; ++v) {
          if (!insideInfluence(volumes[v], p.pointMeters)) continue;
          inner = insideInnerRange(volumes[v], p.pointMeters);  // inner lies in the outer range
          p.volumes.push_back(static_cast<int>(v));
        }
        if (!inner && static_cast<int>(p.volumes.size()) > options.maxOverlap)
          over.push_back(std::move(p));
      }
    }
  }
  // Inside a wall or a floor slab, where volumes meet as they reach past their floor, no
  // camera goes.
  std::vector<glm::dvec3> points;
  for (const OverlapPoint& p : over) points.push_back(p.pointMeters);
  std::vector<char> cameras(points.size(), 0);
  markCameraSpace(level, walked, options.cameraHeadRoomMeters, points, cameras);
  for (std::size_t i = 0; i < over.size(); ++i)
    if (cameras[i]) out.points.push_back(std::move(over[i]));
  return out;
}

}  // namespace probeproxy
