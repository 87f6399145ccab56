// floor_not_covered: walkable floor that no influence volume reaches gets no local reflection
// at all (the sky or a global cubemap shows through).

#include "geometry/survey/blended_error.h"
#include "geometry/validate/validation_rules.h"

#include <glm/geometric.hpp>

#include <cstdio>
#include <limits>

namespace probeproxy {

void checkFloorCoverage(const Scene& scene, const std::vector<FloorCell>& floor,
                        const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (scene.probes.empty()) return;
  double uncovered = 0.0;
  std::optional<glm::dvec3> example;
  for (const FloorCell& f : floor) {
    const glm::dvec3 p = f.pointMeters + glm::dvec3(0, 0, kBlendLiftMeters);
    bool covered = false;
    for (const Probe& probe : scene.probes)
      covered = covered || insideInfluence(probe.influence, p);
    if (covered) continue;
    uncovered += f.areaSquareMeters;
    if (!example) example = f.pointMeters;
  }
  if (uncovered <= options.maxUncoveredFloorSquareMeters) return;
  // The probe to blame: the one whose capture point is nearest the uncovered floor.
  const Probe* nearest = &scene.probes.front();
  double best = std::numeric_limits<double>::infinity();
  for (const Probe& probe : scene.probes) {
    const double d = glm::distance(probe.captureMeters, *example);
    if (d < best) best = d, nearest = &probe;
  }
  char text[160];
  std::snprintf(text, sizeof text, "%.2f m^2 of walkable floor is in no influence volume, e.g. at ",
                uncovered);
  out.push_back(
      {nearest->name, "floor_not_covered", "warning", uncovered,
       options.maxUncoveredFloorSquareMeters,
       std::string(text) + formatPoint(*example) + " (nearest probe: '" + nearest->name + "')",
       "enlarge '" + nearest->name + "' influence volume over that floor, or place a probe there"});
}

}  // namespace probeproxy
