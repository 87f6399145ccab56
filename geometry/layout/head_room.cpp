#include "geometry/layout/head_room.h"

#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_influence.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace probeproxy {

namespace {

bool holdsInPlan(const InnerRange& r, glm::dvec3 p) {
  return p.x >= r.lo.x && p.x <= r.hi.x && p.y >= r.lo.y && p.y <= r.hi.y;
}

bool holds(const InnerRange& r, glm::dvec3 p) {
  return holdsInPlan(r, p) && p.z >= r.lo.z && p.z <= r.hi.z;
}

// The grid columns (as a FloorRect of `floor`) under a plan rectangle.
FloorRect columnsUnder(const WalkableFloor& floor, glm::dvec2 lo, glm::dvec2 hi) {
  const auto index = [&](double meters, double origin) {
    return static_cast<int>(std::floor((meters - origin) / floor.spacingMeters));
  };
  FloorRect r;
  r.column0 = index(lo.x, floor.originMeters.x), r.column1 = index(hi.x, floor.originMeters.x);
  r.row0 = index(lo.y, floor.originMeters.y), r.row1 = index(hi.y, floor.originMeters.y);
  return r;
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
  const WalkableFloor& walked = columns.floor();
  const glm::dvec2 gap(gapMeters);
  const InnerRange around{{glm::dvec2(range.lo) - gap, range.lo.z},
                          {glm::dvec2(range.hi) + gap, range.hi.z}};
  double highest = -INFINITY;
  columns.forEachInPlan(columnsUnder(walked, glm::dvec2(around.lo), glm::dvec2(around.hi)),
                        [&](std::size_t i) {
                          const glm::dvec3 p = walked.cells[i].pointMeters;
                          if (p.z <= highest || !holds(around, p)) return;
                          if (!holdsInPlan(range, p) &&
                              std::any_of(neighbours.begin(), neighbours.end(),
                                          [&](const InnerRange* n) { return holds(*n, p); }))
                            return;
                          highest = p.z;
                        });
  return highest;
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
    const std::vector<const InnerRange*> neighbours = neighboursOf(ranges, self, gapMeters);
    double top =
        highestFloorAround(columns, range, neighbours, gapMeters) + kInfluenceHeadRoomMeters;
    if (!(top > range.hi.z)) continue;
    // Up to the next range above within a gap: ranges that close hand the whole weight over. A
    // range beside its height already (a strip cut back only to its capture point) gets no
    // nearer in plan by the rise; stopping there left cameras over the raised floor in no
    // band but the far ends of others (toxic: 0.15 per cm instead of 0.05).
    for (const InnerRange* n : neighbours)
      if (n->lo.z >= range.hi.z) top = std::min(top, n->lo.z - kInnerClearanceMeters);
    if (!(top > range.hi.z)) continue;
    range.hi.z = top;
    probes[t].influence = influenceOfBounds(range.lo, range.hi, gapMeters);
  }
}

}  // namespace probeproxy
