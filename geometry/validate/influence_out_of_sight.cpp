#include "geometry/validate/influence_out_of_sight.h"

#include "core/blend/influence_factor.h"
#include "geometry/raycast/room_in_sight.h"
#include "geometry/survey/blended_error.h"

#include <vector>

namespace probeproxy {

InfluenceOutOfSight influenceOutOfSight(const LevelRayCaster& level, glm::dvec3 captureMeters,
                                        const InfluenceVolume& influence,
                                        std::span<const FloorCell> floor) {
  const std::vector<glm::dvec3> from = roomViewpoints(level, captureMeters);
  InfluenceOutOfSight out;
  double total = 0.0, hidden = 0.0;
  for (const FloorCell& f : floor) {
    const double factor =
        influenceFactor(influence, f.pointMeters + glm::dvec3(0, 0, kBlendLiftMeters));
    if (factor <= 0.0) continue;
    total += factor;
    if (roomInSight(level, from, roomTargetsOver(level, f.pointMeters))) continue;
    if (!out.firstHiddenMeters) out.firstHiddenMeters = f.pointMeters;
    hidden += factor;
  }
  if (total > 0.0) out.share = hidden / total;
  return out;
}

}  // namespace probeproxy
