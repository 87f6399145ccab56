// influence_leak: an influence volume that reaches through a wall lights space its probe has
// never seen (light leaking). Measured on the walkable floor inside the volume: the share of
// the probe's influence (Lagarde's factor, core/blend) that falls on floor hidden from it, so
// a fade band reaching round a corner counts for what it contributes there. Hidden: not in
// sight of the probe by geometry/raycast/room_in_sight.h.

#include "geometry/validate/influence_out_of_sight.h"
#include "geometry/validate/validation_rules.h"

#include <cstdio>

namespace probeproxy {

void checkInfluenceLeak(const LevelRayCaster& level, const Probe& probe,
                        const std::vector<FloorCell>& floor, const ValidateOptions& options,
                        std::vector<ValidationFinding>& out) {
  const InfluenceOutOfSight leak =
      influenceOutOfSight(level, probe.captureMeters, probe.influence, floor);
  const double share = leak.share;
  if (share <= options.maxLeakShare) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "' influence volume: %.1f%% of its influence on walkable floor falls behind a "
                "wall from the capture point, e.g. at ",
                100.0 * share);
  out.push_back({probe.name, "influence_leak", "warning", share, options.maxLeakShare,
                 "probe '" + probe.name + text +
                     formatPoint(leak.firstHiddenMeters.value_or(glm::dvec3(0.0))),
                 "shrink or rotate the influence volume so it stays in the space the probe "
                 "sees, and give the space behind the wall a probe of its own"});
}

}  // namespace probeproxy
