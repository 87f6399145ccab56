#include "geometry/survey/floor_samples.h"

#include "geometry/evaluation/reflection_samples.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

constexpr double kSurfaceOffsetMeters = 1e-4;  // as reflection_samples.cpp's surfaceEpsilon

// A small counter-based stream (splitmix64): one per cell, cheap to seed, so a cell's samples
// depend only on the seed and the cell's index.
struct CellRandom {
  std::uint64_t state;
  double next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;  // [0, 1)
  }
};

// The floor point under a jittered spot of the cell: the surface within a step of the cell's
// height, else the cell's own centre point (a spot over a hole or on a wall's foot).
void placeOnFloor(const LevelRayCaster& level, const WalkableFloor& floor, const FloorCell& cell,
                  double u, double v, const FloorSampleOptions& o, ReflectionSample& s) {
  s.xMeters = cell.pointMeters;
  s.normal = cell.normal;
  // Jittered over the middle 90% of the cell: a point within a hair of a wall that runs along
  // a cell edge would have its reflection ray start past the wall (traceTrueHit skips 0.1 mm
  // of its own surface), and see out of a closed room.
  const double spread = 0.9 * floor.spacingMeters;
  Ray down;
  down.originMeters = {cell.pointMeters.x + (u - 0.5) * spread,
                       cell.pointMeters.y + (v - 0.5) * spread,
                       cell.pointMeters.z + 0.5 * o.stepHeightMeters};
  down.direction = {0.0f, 0.0f, -1.0f};
  down.tMax = static_cast<float>(o.stepHeightMeters);
  const RayHit hit = level.firstHit(down);
  if (!hit.hit() || std::abs(hit.geometricNormal.z) < o.upwardCosine) return;
  s.xMeters = down.originMeters - glm::dvec3(0.0, 0.0, hit.t);
  s.normal = glm::dvec3(hit.geometricNormal);
  if (s.normal.z < 0.0) s.normal = -s.normal;
}

// Whether a camera at distance `distance` back along `view` sees x.
bool cameraSees(const LevelRayCaster& level, const ReflectionSample& s, glm::dvec3 view,
                double distance) {
  const glm::dvec3 back = -view;
  const double tSkip = kSurfaceOffsetMeters / std::max(glm::dot(back, s.normal), 1e-3);
  Ray ray{s.xMeters, glm::vec3(back), static_cast<float>(tSkip), static_cast<float>(distance)};
  return !level.firstHit(ray).hit();
}

void chooseView(const LevelRayCaster& level, CellRandom& random, const FloorSampleOptions& o,
                ReflectionSample& s) {
  glm::dvec3 view(0.0, 0.0, -1.0);
  bool seen = false;
  double heading = 0.0;
  for (int attempt = 0; attempt < o.maxViewAttempts && !seen; ++attempt) {
    const double look = random.next(), depression = random.next();
    heading = random.next();
    view = playerFloorDirection(look, depression, heading);
    seen = cameraSees(level, s, view, o.eyeHeightMeters / -view.z);
  }
  // A spot no drawn view reaches (a closet's corner): the player looks down at it.
  if (!seen) view = playerFloorDirection(0.0, 1.0, heading);
  s.eyeMeters = s.xMeters - view * (o.eyeHeightMeters / -view.z);
  s.reflected = glm::normalize(view - 2.0 * glm::dot(view, s.normal) * s.normal);
}

}  // namespace

std::vector<FloorSample> buildFloorSamples(const LevelRayCaster& level, const WalkableFloor& floor,
                                           const FloorSampleOptions& o) {
  const std::size_t perCell = static_cast<std::size_t>(std::max(1, o.samplesPerCell));
  std::vector<FloorSample> samples(floor.cells.size() * perCell);
  tbb::parallel_for(std::size_t{0}, floor.cells.size(), [&](std::size_t c) {
    const FloorCell& cell = floor.cells[c];
    CellRandom random{(static_cast<std::uint64_t>(o.seed) << 32) ^ (c * 0x2545f4914f6cdd1dull)};
    for (std::size_t k = 0; k < perCell; ++k) {
      FloorSample& f = samples[c * perCell + k];
      f.cell = c;
      f.areaSquareMeters = cell.areaSquareMeters / static_cast<double>(perCell);
      // Stratified in the cell: a row of strata per sample keeps them apart even when few.
      const double u = random.next();
      const double v = (static_cast<double>(k) + random.next()) / static_cast<double>(perCell);
      placeOnFloor(level, floor, cell, u, v, o, f.sample);
      chooseView(level, random, o, f.sample);
      traceTrueHit(level, f.sample);
    }
  });
  return samples;
}

}  // namespace probeproxy
