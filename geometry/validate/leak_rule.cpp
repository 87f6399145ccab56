// influence_leak: an influence volume that reaches through a wall lights space its probe has
// never seen (light leaking). Measured on the walkable floor inside the volume: the share of
// the probe's influence (Lagarde's factor, core/blend) that falls on floor hidden from it, so
// a fade band reaching round a corner counts for what it contributes there. Hidden: not in
// sight of the probe by geometry/raycast/room_in_sight.h.

#include "core/blend/influence_factor.h"
#include "geometry/raycast/room_in_sight.h"
#include "geometry/survey/blended_error.h"
#include "geometry/validate/validation_rules.h"

#include <cstdio>

namespace probeproxy {

void checkInfluenceLeak(const LevelRayCaster& level, const Probe& probe,
                        const std::vector<FloorCell>& floor, const ValidateOptions& options,
                        std::vector<ValidationFinding>& out) {
  const std::vector<glm::dvec3> from = roomViewpoints(level, probe.captureMeters);
  double total = 0.0, hidden = 0.0;
  glm::dvec3 firstHidden(0.0);
  for (const FloorCell& f : floor) {
    const double factor =
        influenceFactor(probe.influence, f.pointMeters + glm::dvec3(0, 0, kBlendLiftMeters));
    if (factor <= 0.0) continue;
    total += factor;
    if (roomInSight(level, from, roomTargetsOver(level, f.pointMeters))) continue;
    if (hidden == 0.0) firstHidden = f.pointMeters;
    hidden += factor;
  }
  if (total == 0.0) return;
  const double share = hidden / total;
  if (share <= options.maxLeakShare) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "' influence volume: %.1f%% of its influence on walkable floor falls behind a "
                "wall from the capture point, e.g. at ",
                100.0 * share);
  out.push_back({probe.name, "influence_leak", "warning", share, options.maxLeakShare,
                 "probe '" + probe.name + text + formatPoint(firstHidden),
                 "shrink or rotate the influence volume so it stays in the space the probe "
                 "sees, and give the space behind the wall a probe of its own"});
}

}  // namespace probeproxy
