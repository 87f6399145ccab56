// influence_leak: an influence volume that reaches through a wall lights space its probe has
// never seen (light leaking). Measured on the walkable floor inside the volume: the share of
// floor points a ray from the capture point cannot reach.

#include "geometry/validate/validation_rules.h"

#include <cstdio>

namespace probeproxy {

namespace {

// Points are tested this far above the floor: where a player's reflections are, and above
// the small clutter that hides floor without any wall in between.
constexpr double kTestHeightMeters = 1.0;
constexpr double kInsideLiftMeters = 0.05;  // floor points sit on the volume's boundary

}  // namespace

void checkInfluenceLeak(const LevelRayCaster& level, const Probe& probe,
                        const std::vector<FloorPoint>& floor, const ValidateOptions& options,
                        std::vector<ValidationFinding>& out) {
  std::vector<Ray> rays;
  for (const FloorPoint& f : floor) {
    if (!insideInfluence(probe.influence, f.pointMeters + glm::dvec3(0, 0, kInsideLiftMeters)))
      continue;
    Ray ray;
    ray.originMeters = probe.captureMeters;
    ray.direction =
        glm::vec3(f.pointMeters + glm::dvec3(0, 0, kTestHeightMeters) - probe.captureMeters);
    ray.tMax = 0.999f;
    rays.push_back(ray);
  }
  if (rays.empty()) return;
  std::vector<RayHit> hits(rays.size());
  level.firstHits(rays, hits);
  std::size_t hidden = 0;
  glm::dvec3 firstHidden(0.0);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].hit()) continue;
    if (hidden++ == 0) firstHidden = rays[i].originMeters + glm::dvec3(rays[i].direction);
  }
  const double share = static_cast<double>(hidden) / static_cast<double>(rays.size());
  if (share <= options.maxLeakShare) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "' influence volume: %.1f%% of its walkable floor is hidden from the capture "
                "point (through a wall), e.g. at ",
                100.0 * share);
  out.push_back({probe.name, "influence_leak", "warning", share, options.maxLeakShare,
                 "probe '" + probe.name + text +
                     formatPoint(firstHidden - glm::dvec3(0, 0, kTestHeightMeters)),
                 "shrink or rotate the influence volume so it stays in the space the probe "
                 "sees, and give the space behind the wall a probe of its own"});
}

}  // namespace probeproxy
