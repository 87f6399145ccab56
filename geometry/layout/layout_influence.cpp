#include "geometry/layout/layout_influence.h"

#include <cmath>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <limits>

namespace probeproxy {

namespace {

// A range cut closer than this over its floor keeps no room for its capture point (half way up
// it, which a scene wants kMinCaptureClearanceMeters off every surface): a platform range that
// starts 0.1 mm over this floor (warfare, with 4 samples a cell) spans the floor as much as one
// that starts under it, and cuts nothing. Skyway has a fill cut 8 cm over its floor: more
// than this would leave that fill's range overlapping the platform's instead.
constexpr double kMinAirOverFloorMeters = 0.05;

// StripForHeadRoom's quarter.
constexpr double kMostPlanShareInAStrip = 0.25;

BoxInfluence boxAround(glm::dvec3 lo, glm::dvec3 hi, double bandMeters) {
  BoxInfluence box;
  box.centerMeters = 0.5 * (lo + hi);
  box.innerHalfExtentsMeters = 0.5 * (hi - lo);
  box.halfExtentsMeters =
      box.innerHalfExtentsMeters +
      glm::dvec3(bandMeters, bandMeters, std::min(bandMeters, kVerticalBandMeters));
  return box;
}

}  // namespace

bool axisAlignedInnerRange(const InfluenceVolume& volume, glm::dvec3& lo, glm::dvec3& hi) {
  const BoxInfluence* box = std::get_if<BoxInfluence>(&volume);
  if (box == nullptr || box->worldFromBox != glm::dquat(1, 0, 0, 0)) return false;
  lo = box->centerMeters - box->innerHalfExtentsMeters;
  hi = box->centerMeters + box->innerHalfExtentsMeters;
  return true;
}

std::optional<InnerRange> innerRangeOf(const InfluenceVolume& volume) {
  InnerRange r;
  if (!axisAlignedInnerRange(volume, r.lo, r.hi)) return std::nullopt;
  return r;
}

BoxInfluence withFaceMovedIn(BoxInfluence box, int axis, int side, double meters) {
  box.centerMeters[axis] -= side * 0.5 * meters;
  box.halfExtentsMeters[axis] -= 0.5 * meters;
  box.innerHalfExtentsMeters[axis] -= 0.5 * meters;
  return box;
}

PlanGap planGap(const InnerRange& a, const InnerRange& b) {
  const glm::dvec2 below = glm::dvec2(a.lo) - glm::dvec2(b.hi);
  const glm::dvec2 above = glm::dvec2(b.lo) - glm::dvec2(a.hi);
  const glm::dvec2 apart = glm::max(below, above);
  const int axis = apart.x >= apart.y ? 0 : 1;
  return {axis, apart[axis], above[axis] >= below[axis] ? 1 : -1};
}

double planApart(const InnerRange& a, const InnerRange& b) { return planGap(a, b).meters; }

BoxInfluence influenceAroundFloor(const WalkableFloor& floor, std::span<const std::size_t> cells,
                                  glm::dvec3 captureMeters, double bandMeters) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity());
  glm::dvec3 hi(-std::numeric_limits<double>::infinity());
  const double half = 0.5 * floor.spacingMeters;
  for (std::size_t c : cells) {
    const glm::dvec3 p = floor.cells[c].pointMeters;
    lo =
        glm::min(lo, p - glm::dvec3(half, half, kInfluenceBelowFloorMeters + kInfluenceStepMeters));
    hi = glm::max(hi, p + glm::dvec3(half, half, kInfluenceHeadRoomMeters));
  }
  lo = glm::min(lo, captureMeters - glm::dvec3(kCaptureMarginMeters));
  hi = glm::max(hi, captureMeters + glm::dvec3(kCaptureMarginMeters));
  return boxAround(lo, hi, bandMeters);
}

BoxInfluence influenceOfBounds(glm::dvec3 innerLoMeters, glm::dvec3 innerHiMeters,
                               double gapMeters) {
  return boxAround(innerLoMeters, innerHiMeters, kOuterBandOverGap * gapMeters);
}

void keepClearOfInnerRanges(glm::dvec3& lo, glm::dvec3& hi, glm::dvec3& captureMeters,
                            double floorMeters, std::span<const InfluenceVolume> others,
                            double gapMeters, StripForHeadRoom strip) {
  const auto meets = [&](glm::dvec3 otherLo, glm::dvec3 otherHi) {
    return !glm::any(glm::greaterThanEqual(lo, otherHi)) &&
           !glm::any(glm::lessThanEqual(hi, otherLo));
  };
  // The side facing the other range, brought back to it on the plan axis that gives up the
  // least (`meters` of it), never past the capture point; side 0 when every side would have to
  // pass it.
  struct PlanCut {
    int axis = 0, side = 0;
    double meters = INFINITY;
  };
  const auto planCut = [&](glm::dvec3 otherLo, glm::dvec3 otherHi) {
    PlanCut cut;
    for (int a = 0; a < 2; ++a) {
      if (otherLo[a] > captureMeters[a] + kCaptureMarginMeters && hi[a] - otherLo[a] < cut.meters)
        cut = {a, 1, hi[a] - otherLo[a]};
      if (otherHi[a] < captureMeters[a] - kCaptureMarginMeters && otherHi[a] - lo[a] < cut.meters)
        cut = {a, -1, otherHi[a] - lo[a]};
    }
    return cut;
  };
  const auto applyPlanCut = [&](const PlanCut& cut, glm::dvec3 otherLo, glm::dvec3 otherHi) {
    if (cut.side > 0) hi[cut.axis] = otherLo[cut.axis];
    if (cut.side < 0) lo[cut.axis] = otherHi[cut.axis];
  };
  const auto planArea = [&] { return (hi.x - lo.x) * (hi.y - lo.y); };
  for (const InfluenceVolume& other : others) {
    glm::dvec3 otherLo, otherHi;
    if (!axisAlignedInnerRange(other, otherLo, otherHi) || !meets(otherLo, otherHi)) continue;
    // A range over or under this floor takes the height it spans, unless it only reaches over
    // an edge of the plan: a raised floor beside this one whose range overhangs it by a strip
    // (warfare) would take this range's head room over all its floor, and leave the air there,
    // where a camera stands, in no volume at all. There the side comes back instead, when that
    // gives up little of the plan (a bridge over the middle, a storey or an artist's volume
    // over most of it, take the height: the air they leave is theirs).
    double newZ = 0.0;
    int heightSide = 0;
    if (otherLo.z > floorMeters + kMinAirOverFloorMeters)
      newZ = otherLo.z - kInnerClearanceMeters, heightSide = 1;
    else if (otherHi.z <= floorMeters)
      newZ = otherHi.z + kInnerClearanceMeters, heightSide = -1;
    if (heightSide == 0) continue;
    const PlanCut cut = planCut(otherLo, otherHi);
    const int across = 1 - cut.axis;
    const bool aQuarterAtMost =
        cut.meters * (hi[across] - lo[across]) <= kMostPlanShareInAStrip * planArea();
    // The strip, then the gap kept in plan from the range beside (below).
    const bool leavesAGap = hi[cut.axis] - lo[cut.axis] - cut.meters - gapMeters >= gapMeters;
    if (cut.side != 0 && (aQuarterAtMost ||
                          (strip == StripForHeadRoom::atMostAQuarterOrLeavingAGap && leavesAGap))) {
      applyPlanCut(cut, otherLo, otherHi);
      continue;
    }
    if (heightSide > 0) hi.z = newZ;
    if (heightSide < 0) lo.z = newZ;
  }
  if (captureMeters.z > hi.z - kCaptureMarginMeters)
    captureMeters.z = floorMeters + 0.5 * (hi.z - floorMeters);
  // Two ranges' boxes can still overlap over plan where neither holds floor (a pillar's column,
  // a pit beside a grating: the selection claims floor cells, not plan; bloodprison, darkzone):
  // the side facing the other comes back off it, never past the capture point.
  for (const InfluenceVolume& other : others) {
    glm::dvec3 otherLo, otherHi;
    if (!axisAlignedInnerRange(other, otherLo, otherHi) || !meets(otherLo, otherHi)) continue;
    applyPlanCut(planCut(otherLo, otherHi), otherLo, otherHi);
  }
  // After the height cuts: a range cut under a platform no longer meets it.
  for (const InfluenceVolume& other : others) {
    glm::dvec3 otherLo, otherHi;
    if (!axisAlignedInnerRange(other, otherLo, otherHi) || lo.z >= otherHi.z || hi.z <= otherLo.z)
      continue;
    const PlanGap apart = planGap({lo, hi}, {otherLo, otherHi});
    const int axis = apart.axis;
    // Overlapping in plan (one spans the other's floor) or already a gap apart on some axis.
    if (apart.meters < 0.0 || apart.meters >= gapMeters) continue;
    const double missing = gapMeters - apart.meters;
    if (apart.side > 0)
      hi[axis] = std::max(hi[axis] - missing, captureMeters[axis] + kCaptureMarginMeters);
    else
      lo[axis] = std::min(lo[axis] + missing, captureMeters[axis] - kCaptureMarginMeters);
  }
}

}  // namespace probeproxy
