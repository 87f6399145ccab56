#pragma once
// Where the blend still pops once every volume is made, trimmed and parted: validate's
// weight_jump, a weight that changes faster than its limit (2 per metre) between neighbouring
// points where a camera can be. What is left there after the earlier steps is mostly bands
// whose far ends alone reach a floor (a corner of four ranges, a ramp beside a stair): each
// weighs little there, so a band coming in takes a large share of the blend within
// centimetres; Lagarde's weight of a band d metres in, (1 - a) / a with a = 1 - d / b, turns by
// about 1 / (b x the others' weight) per metre, over the limit once the band is short for the
// others' weight where it begins (downer's probe_118 entering where probe_125's band is 0.77
// of the way out: 2.1 per metre).
//
// So the layout measures its blend as validate does, over the walked floor at validate's
// planes (camera_planes.h), and where it turns faster than 0.9 of the limit it widens a fade: a
// volume reaching the spot shrinks its inner range along one horizontal axis (its band grows
// inwards, its outer range stays: nothing reaches further), or else grows its outer range
// (where two bands' far ends alone meet, the share turns across the width both reach, and only
// reaching further widens it). The first (volumes in order, the pop's axis first, the least
// change first) that brings the spot under 0.9 of the limit is kept, if away from the spot no
// cell over the box turns steeper than that or than it did, no more volumes meet over a camera
// than the blend takes or than did, and a grown range keeps its influence out of its probe's
// sight under bands_in_sight.h's target or where it was.
//
// A band that pops along its length shows in every cell beside it: once no widening of the
// volumes reaching one spot helped, the band's other spots are not tried again until one of
// those volumes changes. Where a camera can be is measured once per cell and height. On an open
// level the work keeps in proportion to the floor (layout.md, "A level too big for one
// machine"): a scan finds its cells by row and column and its volumes from columns over the
// level, and a widening's check stops at the first cell it made worse, nearest the spot first,
// and passes by the cells whose blend the widening leaves as it was.

#include "core/scene/influence_volume.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/validate/validate_scene.h"

#include <span>
#include <vector>

namespace probeproxy {

// `probes`: the layout's own (axis-aligned boxes from influenceOfBounds), widened in place;
// `kept`: volumes blended with them, never changed (an artist's, kept by --keep-authored).
// `limits`: the validate options the layout must pass (maxWeightJumpPerCentimeter, maxOverlap,
// cameraHeadRoomMeters). Deterministic whatever the thread count: spots worst first, ties by
// position. Returns how many fades it widened.
std::size_t widenFadesWhereWeightsJump(const LevelRayCaster& level, const WalkableFloor& walked,
                                       double gapMeters, const ValidateOptions& limits,
                                       std::span<const InfluenceVolume> kept,
                                       std::vector<LayoutProbe>& probes);

}  // namespace probeproxy
