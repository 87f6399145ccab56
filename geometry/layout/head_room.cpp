#include "geometry/layout/head_room.h"

#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_influence.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace probeproxy {

namespace {

bool holdsInPlan(const InnerRange& r, glm::dvec3 p) {
  return p.x >= r.lo.x && p.x <= r.hi.x && p.y >= r.lo.y && p.y <= r.hi.y;
}

// Calls f(point) for every walked floor cell in the range widened by a gap in plan, over the
// range's heights.
void forEachFloorAround(const FloorColumns& columns, const InnerRange& range, double gapMeters,
                        const std::function<void(glm::dvec3)>& f) {
  const WalkableFloor& walked = columns.floor();
  const glm::dvec2 gap(gapMeters);
  const InnerRange around{{glm::dvec2(range.lo) - gap, range.lo.z},
                          {glm::dvec2(range.hi) + gap, range.hi.z}};
  const auto index = [&](double meters, double origin) {
    return static_cast<int>(std::floor((meters - origin) / walked.spacingMeters));
  };
  FloorRect under;  // the grid columns under `around`
  under.column0 = index(around.lo.x, walked.originMeters.x);
  under.column1 = index(around.hi.x, walked.originMeters.x);
  under.row0 = index(around.lo.y, walked.originMeters.y);
  under.row1 = index(around.hi.y, walked.originMeters.y);
  columns.forEachInPlan(under, [&](std::size_t i) {
    if (holds(around, walked.cells[i].pointMeters)) f(walked.cells[i].pointMeters);
  });
}

// The ranges within a gap of `range` in plan (overlapping it in plan too).
std::vector<const InnerRange*> neighboursOf(const std::vector<std::optional<InnerRange>>& ranges,
                                            std::size_t self, double gapMeters) {
  std::vector<const InnerRange*> near;
  for (std::size_t o = 0; o < ranges.size(); ++o)
    if (o != self && ranges[o] && planApart(*ranges[o], *ranges[self]) < gapMeters)
      near.push_back(&*ranges[o]);
  return near;
}

// The highest floor in the range's height window under it, or in the gap around it where no
// other range holds the floor.
double highestFloorAround(const FloorColumns& columns, const InnerRange& range,
                          std::span<const InnerRange* const> neighbours, double gapMeters) {
  double highest = -INFINITY;
  forEachFloorAround(columns, range, gapMeters, [&](glm::dvec3 p) {
    if (p.z <= highest) return;
    if (!holdsInPlan(range, p) && std::any_of(neighbours.begin(), neighbours.end(),
                                              [&](const InnerRange* n) { return holds(*n, p); }))
      return;
    highest = p.z;
  });
  return highest;
}

double planArea(const InnerRange& r) { return (r.hi.x - r.lo.x) * (r.hi.y - r.lo.y); }

// A cut in plan gives floor to the bands; more than this and the floor given up wants ranges of
// its own (warfare: fills over a range cut by half, overlapping it).
constexpr double kKeptPlanShare = 0.8;

// How far a floor point lies outside a range in plan, as planApart measures ranges.
double planApart(const InnerRange& r, glm::dvec3 p) { return planApart(r, InnerRange{p, p}); }

// Cuts `range` back in plan to a gap from `other`, on the side that keeps the most of it,
// keeping the capture point inside and at least a gap across; false (and no cut) when no side
// can.
bool cutAwayInPlan(InnerRange& range, const InnerRange& other, glm::dvec3 captureMeters,
                   double gapMeters) {
  std::optional<InnerRange> best;
  for (int axis = 0; axis < 2; ++axis) {
    for (int side = 0; side < 2; ++side) {
      InnerRange cut = range;
      if (side == 0) {
        cut.hi[axis] = std::min(cut.hi[axis], other.lo[axis] - gapMeters);
        if (cut.hi[axis] < captureMeters[axis] + kCaptureMarginMeters) continue;
      } else {
        cut.lo[axis] = std::max(cut.lo[axis], other.hi[axis] + gapMeters);
        if (cut.lo[axis] > captureMeters[axis] - kCaptureMarginMeters) continue;
      }
      if (cut.hi[axis] - cut.lo[axis] < gapMeters) continue;
      if (!best || planArea(cut) > planArea(*best)) best = cut;
    }
  }
  if (best) range = *best;
  return best.has_value();
}

// Whether all floor in the old range's height window under it or a gap around it stays within
// a gap of the cut range or of another range over its height: the selection keeps every floor
// cell that near some range, and farther out only the far ends of bands reach it.
bool keepsFloorNear(const FloorColumns& columns, const InnerRange& before, const InnerRange& cut,
                    std::span<const InnerRange* const> neighbours, double gapMeters) {
  bool near = true;
  forEachFloorAround(columns, before, gapMeters, [&](glm::dvec3 p) {
    if (!near || planApart(cut, p) <= gapMeters) return;
    near = std::any_of(neighbours.begin(), neighbours.end(), [&](const InnerRange* n) {
      return p.z >= n->lo.z && p.z <= n->hi.z && planApart(*n, p) <= gapMeters;
    });
  });
  return near;
}

}  // namespace

void raiseRangesOverRaisedFloor(const WalkableFloor& walked, double gapMeters,
                                std::span<const InfluenceVolume> kept,
                                std::vector<LayoutProbe>& probes) {
  std::vector<std::optional<InnerRange>> ranges;
  for (const InfluenceVolume& v : kept) ranges.push_back(innerRangeOf(v));
  for (const LayoutProbe& p : probes) ranges.push_back(innerRangeOf(p.influence));
  const FloorColumns columns(walked);
  for (std::size_t t = 0; t < probes.size(); ++t) {
    const std::size_t self = kept.size() + t;
    if (!ranges[self]) continue;
    InnerRange& range = *ranges[self];
    std::vector<const InnerRange*> neighbours = neighboursOf(ranges, self, gapMeters);
    double top =
        highestFloorAround(columns, range, neighbours, gapMeters) + kInfluenceHeadRoomMeters;
    if (!(top > range.hi.z)) continue;
    const InnerRange before = range;
    // A range above within a gap that would stop the rise short of a camera's head (a ramp up
    // to the floor that range holds): this one gives it the gap in plan instead, and the ramp's
    // top lies in the blend between the two. One it cannot give the gap to (the storey over
    // all of it) still bounds the rise; those lower than that are given the gap, so a strip
    // beside the stair's top does not hold the range under it (stormkeep: a camera over the
    // stair stood between the storeys' bands, in no volume but the strip's band end).
    const auto above = [&](const InnerRange* n) {
      return n->lo.z >= range.hi.z && n->lo.z < top - kVerticalBandMeters;
    };
    double bound = top;
    for (const InnerRange* n : neighbours) {
      InnerRange alone = range;
      if (above(n) && !cutAwayInPlan(alone, *n, probes[t].captureMeters, gapMeters))
        bound = std::min(bound, n->lo.z);
    }
    InnerRange cut = range;
    bool cuts = false, uncut = false;
    for (const InnerRange* n : neighbours) {
      if (!above(n) || n->lo.z >= bound) continue;
      cuts = true;
      uncut = uncut || !cutAwayInPlan(cut, *n, probes[t].captureMeters, gapMeters);
    }
    if (cuts && !uncut && planArea(cut) >= kKeptPlanShare * planArea(range) &&
        keepsFloorNear(columns, range, cut, neighbours, gapMeters)) {
      range = cut;
      neighbours = neighboursOf(ranges, self, gapMeters);
      top = highestFloorAround(columns, range, neighbours, gapMeters) + kInfluenceHeadRoomMeters;
    }
    // Up to the next range above within a gap: ranges that close hand the whole weight over. A
    // range beside its height already (a strip cut back only to its capture point) gets no
    // nearer in plan by the rise; stopping there left cameras over the raised floor in no
    // band but the far ends of others (toxic: 0.15 per cm instead of 0.05).
    for (const InnerRange* n : neighbours)
      if (n->lo.z >= range.hi.z) top = std::min(top, n->lo.z - kInnerClearanceMeters);
    range.hi.z = std::max(range.hi.z, top);
    if (range.lo != before.lo || range.hi != before.hi)
      probes[t].influence = influenceOfBounds(range.lo, range.hi, gapMeters);
  }
}

}  // namespace probeproxy
