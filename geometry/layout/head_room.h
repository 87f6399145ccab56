#pragma once
// A range's height window holds floor up to head room over its storey's floor (a ramp, a
// stair's upper steps, a ledge), yet its top is head room over the storey's floor alone and its
// band reaches only kVerticalBandMeters higher: a camera over the raised floor stands above
// both, where only the far ends of neighbours' bands reach, and their normalised weights swing
// from one probe to another within a few centimetres (validate's weight_jump: warfare, toxic,
// stormkeep, skyway, ruiner, downer, each over floor 1-2 m above its range's storey). So a
// range's top rises to head room over the highest walked floor under it or in the gap around
// it (floor no other range holds), no higher than the bottom of any range above it within a
// gap in plan: inner ranges never meet, and stay a gap apart wherever they did. A range under
// such a range (a ramp up to the floor that one holds: downer) first gives it the gap in plan
// where that keeps most of its plan and all of its floor within a gap of some range.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"

#include <span>
#include <vector>

namespace probeproxy {

// `probes`: the layout's own (axis-aligned boxes from influenceOfBounds); `kept`: volumes whose
// inner ranges they must keep clear of. Ranges rise in order, each against the others as they
// are by then (deterministic); capture points stay.
void raiseRangesOverRaisedFloor(const WalkableFloor& walked, double gapMeters,
                                std::span<const InfluenceVolume> kept,
                                std::vector<LayoutProbe>& probes);

}  // namespace probeproxy
