#include "geometry/floor/floor_seed.h"

#include "geometry/raycast/ray.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

namespace probeproxy {

namespace {

// The largest triangles tried as seeds: a level's floors are among its largest upward faces.
constexpr std::size_t kTriedTriangles = 64;
constexpr double kSeedLiftMeters = 0.5;
constexpr double kSmallestRegionShare = 0.25;  // of the largest region's area

struct UpwardTriangle {
  double area = 0.0;
  glm::dvec3 centre{0.0};
  std::size_t index = 0;
};

}  // namespace

std::vector<FloorSeed> floorRegionSeeds(const LevelMesh& mesh, const LevelRayCaster& level,
                                        const WalkableFloorOptions& options) {
  std::vector<UpwardTriangle> roofed, open;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::uvec3 t = mesh.triangles[i];
    const glm::dvec3 a(mesh.positionsMeters[t.x]), b(mesh.positionsMeters[t.y]),
        c(mesh.positionsMeters[t.z]);
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double twiceArea = glm::length(cross);
    if (!(twiceArea > 0.0) || cross.z / twiceArea < options.upwardCosine) continue;
    const UpwardTriangle up{0.5 * twiceArea, (a + b + c) / 3.0, i};
    // Inside a level a floor has something over it; a roof or the ground outside has the sky.
    const Ray skyward{up.centre + glm::dvec3(0, 0, 1e-3), glm::vec3(0, 0, 1)};
    (level.firstHit(skyward).hit() ? roofed : open).push_back(up);
  }
  std::vector<UpwardTriangle>& tried = roofed.empty() ? open : roofed;
  std::stable_sort(
      tried.begin(), tried.end(),
      [](const UpwardTriangle& x, const UpwardTriangle& y) { return x.area > y.area; });
  if (tried.size() > kTriedTriangles) tried.resize(kTriedTriangles);

  std::vector<FloorSeed> seeds;
  std::vector<WalkableFloor> regions;  // found so far: a seed inside one floods it again
  for (const UpwardTriangle& t : tried) {
    const bool known = std::any_of(regions.begin(), regions.end(), [&](const WalkableFloor& f) {
      return f.reaches(t.centre, options.stepHeightMeters);
    });
    if (known) continue;
    const glm::dvec3 seed = t.centre + glm::dvec3(0, 0, kSeedLiftMeters);
    WalkableFloor floor = walkableFloor(level, std::span(&seed, 1), options);
    if (floor.cells.empty()) continue;
    seeds.push_back({seed, floor.areaSquareMeters()});
    regions.push_back(std::move(floor));
  }
  std::stable_sort(seeds.begin(), seeds.end(), [](const FloorSeed& x, const FloorSeed& y) {
    return x.floorSquareMeters > y.floorSquareMeters;
  });
  std::erase_if(seeds, [&](const FloorSeed& s) {
    return s.floorSquareMeters < kSmallestRegionShare * seeds.front().floorSquareMeters;
  });
  return seeds;
}

}  // namespace probeproxy
