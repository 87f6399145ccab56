#pragma once
// Where three ranges meet at a T across their gaps and a fourth's corner or a thin strip is
// near, four or five bands 1.5 gaps deep cross over the gap: more outer ranges than the blend
// takes meet outside every inner range, where a camera stands (validate's too_many_overlaps:
// eggandbacon's five over 1.25 m^3 beside a 0.5 m strip, skyway, stormkeep, toxic,
// bloodprison). A probe drops out of the blend there and its lighting pops. So the band of a
// volume that reaches such a point is trimmed back off it: the trim that frees the most such
// points for the least band first. A box keeps one centre, so its band shrinks on both sides of
// that axis; it keeps at least a gap (a floor cell lies within a gap of some range), the floor
// it gives up stays in another volume, and near the volume the blend's steepest change stays
// under validate's limit (or no steeper than before): otherwise the trim is not made.
//
// An optional fill (uncovered_floor_fills.h) serves floor whose cameras only band ends reach, a
// group wider than the pop it closes, and its band is one gap: no trim takes it out of a crowd.
// Its faces may move instead: one side of its box, inner range and band together, moves in off
// the points (bloodprison's fill over a capped ramp met four bands below its end; dropped, its
// pop came back: 0.205 per cm), the box keeping its capture point: only where no band trim is
// left to try, the floor it gives up staying in another volume, and the blend over its box no
// steeper than validate's limit or than without the fill, the alternative.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/validate/overlap_points.h"
#include "geometry/validate/validate_scene.h"

#include <set>
#include <span>
#include <vector>

namespace probeproxy {

// `probes`: the layout's own (axis-aligned boxes from influenceOfBounds), trimmed in place;
// `kept`: volumes counted but never trimmed (an artist's, kept by --keep-authored). `limits`:
// the validate options the layout must pass (maxOverlap, maxWeightJumpPerCentimeter,
// cameraHeadRoomMeters, the grid). Deterministic: one trim at a time, ties by index. Returns
// the points still over the limit (their volumes: indices into kept, then probes).
// `facesMove`: the probes (indices into `probes`) whose faces may move in.
std::vector<OverlapPoint> trimBandsOverOverlapLimit(const LevelRayCaster& level,
                                                    const WalkableFloor& walked, double gapMeters,
                                                    const ValidateOptions& limits,
                                                    std::span<const InfluenceVolume> kept,
                                                    std::vector<LayoutProbe>& probes,
                                                    const std::set<std::size_t>& facesMove = {});

}  // namespace probeproxy
