// The scene-wide rules on influence volumes: too many outer ranges at one point (each one
// more is a probe whose weight can pop in or out there), and inner ranges that overlap (two
// probes that each claim 100% of the same space).

#include "geometry/validate/camera_space.h"
#include "geometry/validate/validation_rules.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>

namespace probeproxy {

namespace {

// Strictly inside the inner range: two ranges that only touch share no volume.
bool insideInnerRange(const InfluenceVolume& influence, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 local = glm::conjugate(box->worldFromBox) * (p - box->centerMeters);
    return glm::all(glm::lessThan(glm::abs(local), box->innerHalfExtentsMeters));
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return glm::distance(p, sphere.centerMeters) < sphere.innerRadiusMeters;
}

// Cell centres of a regular grid over [lo, hi], coarsened to stay within the budget.
struct Grid {
  glm::dvec3 lo{0.0}, cell{1.0};
  glm::ivec3 count{0};
  double cellVolume() const { return cell.x * cell.y * cell.z; }
  glm::dvec3 at(int i, int j, int k) const { return lo + (glm::dvec3(i, j, k) + 0.5) * cell; }
};

Grid makeGrid(glm::dvec3 lo, glm::dvec3 hi, const ValidateOptions& options) {
  const glm::dvec3 size = glm::max(hi - lo, glm::dvec3(0.0));
  double spacing = options.gridSpacingMeters;
  const glm::dvec3 n = size / spacing + 1.0;
  const double points = n.x * n.y * n.z;
  const double budget = static_cast<double>(options.gridPointBudget);
  if (points > budget) spacing *= std::cbrt(points / budget);
  Grid grid;
  grid.lo = lo;
  grid.count = glm::max(glm::ivec3(glm::ceil(size / spacing)), glm::ivec3(1));
  grid.cell = size / glm::dvec3(grid.count);
  return grid;
}

template <class F>
void forEachPoint(const Grid& grid, F&& f) {
  for (int k = 0; k < grid.count.z; ++k)
    for (int j = 0; j < grid.count.y; ++j)
      for (int i = 0; i < grid.count.x; ++i) f(grid.at(i, j, k));
}

}  // namespace

void checkOverlaps(const Scene& scene, const LevelRayCaster& level, const WalkableFloor& walked,
                   const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (static_cast<int>(scene.probes.size()) <= options.maxOverlap) return;
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Probe& probe : scene.probes) {
    glm::dvec3 a, b;
    influenceBounds(probe.influence, a, b);
    lo = glm::min(lo, a), hi = glm::max(hi, b);
  }
  // Points over the limit where the blend can pop, then only those where a camera can be.
  // Inside an inner range one probe takes 100% however many volumes overlap there (seed 000):
  // none drops out. Inside a wall or a floor slab, where volumes meet as they reach past their
  // floor, no camera goes.
  std::vector<glm::dvec3> over;
  std::vector<int> counts;
  const Grid grid = makeGrid(lo, hi, options);
  forEachPoint(grid, [&](glm::dvec3 p) {
    int count = 0;
    for (const Probe& probe : scene.probes) {
      if (!insideInfluence(probe.influence, p)) continue;
      if (insideInnerRange(probe.influence, p)) return;  // inner ranges lie in the outer ones
      ++count;
    }
    if (count > options.maxOverlap) over.push_back(p), counts.push_back(count);
  });
  std::vector<char> cameras(over.size(), 0);
  markCameraSpace(level, walked, options.cameraHeadRoomMeters, over, cameras);
  int worst = 0;
  std::size_t open = 0;
  glm::dvec3 worstPoint(0.0);
  for (std::size_t i = 0; i < over.size(); ++i) {
    if (!cameras[i]) continue;
    ++open;
    if (counts[i] > worst) worst = counts[i], worstPoint = over[i];
  }
  if (worst <= options.maxOverlap) return;
  std::string names, first;
  for (const Probe& probe : scene.probes) {
    if (!insideInfluence(probe.influence, worstPoint)) continue;
    if (first.empty()) first = probe.name;
    names += (names.empty() ? "'" : ", '") + probe.name + "'";
  }
  char extent[64];
  std::snprintf(extent, sizeof extent, " (%.2f m^3 in all)",
                static_cast<double>(open) * grid.cellVolume());
  std::string message = std::to_string(worst) + " influence volumes overlap at ";
  message += formatPoint(worstPoint) + " (" + names + "), more than " +
             std::to_string(options.maxOverlap) + extent +
             ": lighting pops where a probe drops out";
  out.push_back({first, "too_many_overlaps", "warning", static_cast<double>(worst),
                 static_cast<double>(options.maxOverlap), std::move(message),
                 "shrink the influence volumes so that at most " +
                     std::to_string(options.maxOverlap) +
                     " meet at any point, or remove a probe there"});
}

void checkInnerRanges(const Scene& scene, const ValidateOptions& options,
                      std::vector<ValidationFinding>& out) {
  for (std::size_t a = 0; a < scene.probes.size(); ++a) {
    for (std::size_t b = a + 1; b < scene.probes.size(); ++b) {
      const Probe& pa = scene.probes[a];
      const Probe& pb = scene.probes[b];
      glm::dvec3 loA, hiA, loB, hiB;
      influenceBounds(pa.influence, loA, hiA);
      influenceBounds(pb.influence, loB, hiB);
      const glm::dvec3 lo = glm::max(loA, loB), hi = glm::min(hiA, hiB);
      if (glm::any(glm::greaterThanEqual(lo, hi))) continue;
      const Grid grid = makeGrid(lo, hi, options);
      std::size_t shared = 0;
      glm::dvec3 sum(0.0);
      forEachPoint(grid, [&](glm::dvec3 p) {
        if (insideInnerRange(pa.influence, p) && insideInnerRange(pb.influence, p))
          ++shared, sum += p;
      });
      const double volume = static_cast<double>(shared) * grid.cellVolume();
      if (shared == 0 || volume <= options.maxInnerOverlapCubicMeters) continue;
      char text[160];
      std::snprintf(text, sizeof text, "' overlap by %.2f m^3 around ", volume);
      out.push_back({pa.name, "inner_ranges_overlap", "warning", volume,
                     options.maxInnerOverlapCubicMeters,
                     "the inner ranges of probes '" + pa.name + "' and '" + pb.name + text +
                         formatPoint(sum / static_cast<double>(shared)) +
                         ": both claim 100% there, so the weights jump at the range edges",
                     "shrink the inner ranges (inner_half_extents / inner_radius) until they only "
                     "touch; the fade between the probes belongs in the outer ranges"});
    }
  }
}

}  // namespace probeproxy
