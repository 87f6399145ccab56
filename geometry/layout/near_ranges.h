#pragma once
// Two inner ranges beside each other in plan, at overlapping heights, hand the whole weight
// from one probe to the other across the gap between them: across g metres with bands b deep
// the steepest change is 1 / (g (1 - g / (2 b))) per metre, over validate's limit (2 per metre)
// once g < 0.63 m with the layout's bands. The selection keeps a gap between its ranges and each
// range added later keeps clear of those before it (keepClearOfInnerRanges), but never past its
// own capture point: a range whose capture point stands by its near side stays 0.2 m from the
// range beside it (toxic: probe_080 and probe_130, 0.053 per cm; skyway, warfare, bloodprison's
// 0.075 m). So once every range is made, a pair nearer than 0.7 gaps moves its facing sides
// apart to that (1.86 per metre), the side of the one with more room to give first (inner
// range and band together, the band keeping its width), then the other's; what floor a range
// gives up lies within a gap of it, in its band.

#include "core/scene/influence_volume.h"
#include "geometry/layout/run_layout.h"

#include <span>
#include <vector>

namespace probeproxy {

// `probes`: the layout's own (axis-aligned boxes from influenceOfBounds), cut in place; `kept`:
// volumes they part from, never cut. A side never passes its capture point (nor comes
// nearer it than a capture margin). Deterministic: pairs in order.
void partNearRanges(double gapMeters, std::span<const InfluenceVolume> kept,
                    std::vector<LayoutProbe>& probes);

}  // namespace probeproxy
