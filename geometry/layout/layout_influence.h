#pragma once
// A probe's influence volume around the floor it serves: an axis-aligned box whose inner range
// holds that floor (its cells whole, from just under the lowest to head room over the highest)
// and the capture point, and whose outer range reaches `bandMeters` further, into the
// neighbours', so the blend fades across the band instead of jumping at its edge. Upwards
// and downwards the band is short: storeys meet through a slab, not a band, and a full band
// would reach through the slab into the room below or above (the U's ground floor had five
// volumes over it, two of its own and three from upstairs).

#include "core/scene/influence_volume.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/floor_rectangles.h"

#include <glm/vec3.hpp>

#include <optional>
#include <span>

namespace probeproxy {

// The outer range reaches this many gaps past the inner one. Were it one gap, floor where
// gaps meet askew (a T of three ranges, the courtyard's corner) lies at the outer edge of
// every volume over it: all weights tend to 0 there and their normalised shares swing from
// one probe to another within a centimetre (validate's weight_jump: 1.0). Half as much again
// keeps all floor at most 5/6 of the way out (a floor cell lies within a gap of some range,
// select_probes.h, its far edge 1.25 gaps away), so where a second band begins beside a lone
// one the weights turn at most ~1.3 per metre (the U's bend: 3 per metre at 1.25 gaps); in a
// straight gap of g metres the steepest change is 1 / (g (1 - g / (2 b))) = 1.5 per metre for
// g = 1, b = 1.5 (2.0 at b = g). validate's limit is 2 per metre (0.02 per cm).
inline constexpr double kOuterBandOverGap = 1.5;

// Head room ends 2.5 m over a floor (kInfluenceHeadRoomMeters) and an inner range starts
// 0.5 m under it (floor_rectangles.h): a 0.25 m band keeps a 3 m storey under a 0.5 m slab
// clear of the next.
inline constexpr double kVerticalBandMeters = 0.25;

// Ranges cut to meet stay this far apart, so that the scene file's rounding of centres and
// extents cannot make them overlap (skyway: by 1e-9 m).
inline constexpr double kInnerClearanceMeters = 1e-3;

// `cells` index floor.cells; at least one.
BoxInfluence influenceAroundFloor(const WalkableFloor& floor, std::span<const std::size_t> cells,
                                  glm::dvec3 captureMeters, double bandMeters);

// The inner range of one of the layout's own volumes (an axis-aligned box); false for any
// other volume (a rotated box, a sphere: an authored one kept by --keep-authored).
bool axisAlignedInnerRange(const InfluenceVolume& volume, glm::dvec3& lo, glm::dvec3& hi);

struct InnerRange {
  glm::dvec3 lo{0.0}, hi{0.0};
};

// As axisAlignedInnerRange; none for any other volume.
std::optional<InnerRange> innerRangeOf(const InfluenceVolume& volume);

// Whether the range holds the point, faces included.
inline bool holds(const InnerRange& r, glm::dvec3 p) {
  return p.x >= r.lo.x && p.x <= r.hi.x && p.y >= r.lo.y && p.y <= r.hi.y && p.z >= r.lo.z &&
         p.z <= r.hi.z;
}

inline bool overlapInHeight(const InnerRange& a, const InnerRange& b) {
  return a.lo.z < b.hi.z && b.lo.z < a.hi.z;
}

// The box with its `side` (-1 low, +1 high) face along `axis` moved in by `meters`, inner range
// and band together: the band keeps its width, so the blend across it stays as smooth.
BoxInfluence withFaceMovedIn(BoxInfluence box, int axis, int side, double meters);

// How `b` stands from `a` in plan: along the axis they are furthest apart, by how much
// (negative when they overlap in plan), and on which side of `a` (+1 high, -1 low).
struct PlanGap {
  int axis = 0;
  double meters = 0.0;
  int side = 1;
};
PlanGap planGap(const InnerRange& a, const InnerRange& b);

// How far apart in plan (the larger of the two axes' separations; negative when they overlap).
double planApart(const InnerRange& a, const InnerRange& b);

// Which strip of its plan a range overhung by another range (over or under part of its floor)
// gives up to keep its head room (or depth) over the rest. A selected range: at most a quarter
// of its plan (warfare's raised floor overhanging an edge: 7%; a bridge over the middle, a
// storey or an artist's volume over most of it take the height, the air they leave is theirs).
// A fill: that, or any strip that leaves it a gap wide across the cut (past the gap it keeps
// from the range beside), since the fill rounds fill what it gives up (uncovered_floor_fills.cpp;
// runningman: a 16 x 14 m fill cut to 1.5 m tall by a range over a tenth of it). Narrower, a
// fill would keep its head room as a sliver whose band is most of its influence (downer: 10 cm
// wide, its band behind a wall).
enum class StripForHeadRoom { atMostAQuarter, atMostAQuarterOrLeavingAGap };

// An inner range (lo, hi) over a floor at `floorMeters` that reaches into another volume's
// inner range stops where that one begins, over or under its floor: a pit or a lower floor in
// a range's plan, whose box spans the air over it, would otherwise be claimed 100% by both.
// The capture point moves into what is left (half way up it, at most). Where the other range
// spans the floor itself (or starts less than 5 cm over it) nothing is cut. Axis-aligned boxes
// only (a layout's own volumes).
//
// A range beside another in plan whose height overlaps it (floors a ledge apart, which the
// selection's gap between ranges of one height window does not see) also keeps `gapMeters`
// from it across the floor: inner ranges that touch hand the whole weight from one probe to the
// other at the touching face (validate's weight_jump). Its near side comes back, never past its
// capture point; the floor it gives up stays in its band. A range over or under only part of
// the plan, clear of the capture point, takes a strip of the plan instead of the height where
// `strip` allows it.
void keepClearOfInnerRanges(glm::dvec3& lo, glm::dvec3& hi, glm::dvec3& captureMeters,
                            double floorMeters, std::span<const InfluenceVolume> others,
                            double gapMeters, StripForHeadRoom strip);

// The box whose inner range is (lo, hi) (floorRectBounds) and whose outer range reaches
// kOuterBandOverGap x `gapMeters` past it across the floor (kVerticalBandMeters up and down).
BoxInfluence influenceOfBounds(glm::dvec3 innerLoMeters, glm::dvec3 innerHiMeters,
                               double gapMeters);

}  // namespace probeproxy
