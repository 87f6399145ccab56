#pragma once
// A range narrower than the gap across its floor (a strip left between two wider ones, cut back
// to keep the gap, or pulled in from a wall) serves little with its own proxy, yet its band
// reaches as far as any: where ranges alternate with gaps along a row, a point in a thin
// range's strip lies in its band and in both neighbours' (0.5 m between two ranges 1 m off
// each side: three volumes from one row, five with the row across the gap), more than the
// blend takes (validate's too_many_overlaps). Such a range joins the neighbour a gap from it
// on its thin axis when their union keeps the gap to every other range: one probe fewer.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"
#include "geometry/raycast/level_ray_caster.h"

#include <span>
#include <vector>

namespace probeproxy {

// `probes`: the layout's own (axis-aligned boxes from influenceOfBounds); `kept`: volumes they
// must keep clear of. The joined probe keeps the wider one's capture point and fit, its inner
// range the union, pulled into sight again (bands_in_sight.h). Deterministic: thin ranges in
// order, each joining its nearest neighbour (then the one first in order).
void joinThinRanges(const LevelRayCaster& level, const WalkableFloor& walked, double gapMeters,
                    std::span<const InfluenceVolume> kept, std::vector<LayoutProbe>& probes);

}  // namespace probeproxy
