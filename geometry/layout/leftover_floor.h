#pragma once
// Floor no fill could take. A fill's capture point needs clear air over its floor, and on a
// stair under a range above there may be none: aneurysm's one cell of stair 0.5 m under the
// upper storey's range, where every height left its capture point within 8 cm of the steps.
// Such floor joins the volume that reaches it for the least growth: a box keeps one centre, so
// its outer range grows on both faces of each axis that must reach the floor, and its inner
// range stays (the floor lies in its band, where its weight is small but the only one there).
// Only a volume whose capture point sees the floor, grown by at most a gap on any axis:
// validate's floor_not_covered hint, done by the layout so that no surveyed floor is uncovered.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"
#include "geometry/raycast/level_ray_caster.h"

#include <span>
#include <vector>

namespace probeproxy {

// `walked`: the survey's floor, each cell counted as the survey counts a sample (its point
// lifted kBlendLiftMeters); `kept`: volumes that cover floor but are never grown. Grows boxes of
// `probes` in place. Returns the cells still in no volume. Deterministic: cells in floor order,
// ties to the lower probe index.
std::vector<std::size_t> coverLeftoverFloor(const LevelRayCaster& level,
                                            const WalkableFloor& walked, double gapMeters,
                                            std::span<const InfluenceVolume> kept,
                                            std::vector<LayoutProbe>& probes);

}  // namespace probeproxy
