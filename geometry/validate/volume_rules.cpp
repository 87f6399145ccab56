// The scene-wide rules on influence volumes: too many outer ranges at one point (each one
// more is a probe whose weight can pop in or out there), and inner ranges that overlap (two
// probes that each claim 100% of the same space).

#include "geometry/validate/overlap_points.h"
#include "geometry/validate/validation_grid.h"
#include "geometry/validate/validation_rules.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>

namespace probeproxy {

void checkOverlaps(const Scene& scene, const LevelRayCaster& level, const WalkableFloor& walked,
                   const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  std::vector<InfluenceVolume> volumes;
  for (const Probe& probe : scene.probes) volumes.push_back(probe.influence);
  const OverlapPoints over = overlapsOverLimit(volumes, level, walked, options);
  const OverlapPoint* worst = nullptr;
  for (const OverlapPoint& p : over.points)
    if (!worst || p.volumes.size() > worst->volumes.size()) worst = &p;
  if (!worst) return;
  std::string names;
  for (int v : worst->volumes)
    names += (names.empty() ? "'" : ", '") + scene.probes[static_cast<std::size_t>(v)].name + "'";
  char extent[64];
  std::snprintf(extent, sizeof extent, " (%.2f m^3 in all)",
                static_cast<double>(over.points.size()) * over.grid.cellCubicMeters());
  const int count = static_cast<int>(worst->volumes.size());
  std::string message = std::to_string(count) + " influence volumes overlap at ";
  message += formatPoint(worst->pointMeters) + " (" + names + "), more than " +
             std::to_string(options.maxOverlap) + extent +
             ": lighting pops where a probe drops out";
  out.push_back({scene.probes[static_cast<std::size_t>(worst->volumes.front())].name,
                 "too_many_overlaps", "warning", static_cast<double>(count),
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
      const ValidationGrid grid = validationGrid(lo, hi, options);
      std::size_t shared = 0;
      glm::dvec3 sum(0.0);
      forEachPoint(grid, [&](glm::dvec3 p) {
        if (insideInnerRange(pa.influence, p) && insideInnerRange(pb.influence, p))
          ++shared, sum += p;
      });
      const double volume = static_cast<double>(shared) * grid.cellCubicMeters();
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
