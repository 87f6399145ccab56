#include "geometry/layout/bands_in_sight.h"

#include "core/blend/influence_factor.h"
#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/raycast/room_in_sight.h"
#include "geometry/survey/blended_error.h"

#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace probeproxy {

namespace {

struct BandFloor {
  glm::dvec3 pointMeters;
  bool hidden = false;
};

// The share of the box's influence on floor out of sight, as influence_leak measures it.
double hiddenShare(const std::vector<BandFloor>& floor, glm::dvec3 innerLo, glm::dvec3 innerHi,
                   double gapMeters) {
  const InfluenceVolume box = influenceOfBounds(innerLo, innerHi, gapMeters);
  double total = 0.0, hidden = 0.0;
  for (const BandFloor& f : floor) {
    const double factor = influenceFactor(box, f.pointMeters);
    total += factor;
    if (f.hidden) hidden += factor;
  }
  return total > 0.0 ? hidden / total : 0.0;
}

}  // namespace

void pullBandsIntoSight(const LevelRayCaster& level, const WalkableFloor& floor, glm::dvec3 capture,
                        double gapMeters, glm::dvec3& innerLo, glm::dvec3& innerHi) {
  glm::dvec3 outerLo, outerHi;
  influenceBounds(influenceOfBounds(innerLo, innerHi, gapMeters), outerLo, outerHi);
  const std::vector<glm::dvec3> from = roomViewpoints(level, capture);
  std::vector<BandFloor> inBox;
  bool anyHidden = false;
  for (const FloorCell& cell : floor.cells) {
    const glm::dvec3 p = cell.pointMeters + glm::dvec3(0, 0, kBlendLiftMeters);
    if (glm::any(glm::lessThanEqual(p, outerLo)) || glm::any(glm::greaterThanEqual(p, outerHi)))
      continue;
    const bool hidden = !roomInSight(level, from, roomTargetsOver(level, cell.pointMeters));
    inBox.push_back({p, hidden});
    anyHidden = anyHidden || hidden;
  }
  if (!anyHidden) return;
  // A side at a time, as far in as cuts the share most (a step or two in may not help alone:
  // the capture point's own floor loses influence too), until the share is under the rule's
  // limit with room to spare (the rule walks the same floor, but at other heights).
  const double step = floor.spacingMeters;
  const int maxSteps = static_cast<int>(kOuterBandOverGap * gapMeters / step);
  glm::dvec3 lo = innerLo, hi = innerHi;
  double share = hiddenShare(inBox, lo, hi, gapMeters);
  const auto pulled = [&](int side, int steps, glm::dvec3& l, glm::dvec3& h) {
    const int axis = side / 2;
    l = lo, h = hi;
    if (side % 2 == 0)
      l[axis] = std::min(innerLo[axis] + steps * step, capture[axis] - kCaptureMarginMeters);
    else
      h[axis] = std::max(innerHi[axis] - steps * step, capture[axis] + kCaptureMarginMeters);
  };
  std::array<int, 4> steps{};
  const auto shareIfPulled = [&](int side, int k) {
    glm::dvec3 l, h;
    pulled(side, k, l, h);
    return hiddenShare(inBox, l, h, gapMeters);
  };
  const auto pullFurthest = [&](int side, int most, int& bestSide, int& bestSteps,
                                double& bestShare) {
    for (int k = steps[side] + 1; k <= most; ++k) {
      const double s = shareIfPulled(side, k);
      if (s < bestShare) bestShare = s, bestSide = side, bestSteps = k;
    }
  };
  while (share > kLeakShareTarget) {
    int bestSide = -1, bestSteps = 0;
    double bestShare = share;
    for (int side = 0; side < 4; ++side)
      pullFurthest(side, maxSteps, bestSide, bestSteps, bestShare);
    if (bestSide < 0) break;  // floor out of sight under the inner range, or by the capture
    steps[bestSide] = bestSteps;
    pulled(bestSide, bestSteps, lo, hi);
    share = bestShare;
  }
  // Where a strip's band cannot be pulled clear, floor out of sight runs along the strip beside
  // it (downer: a stair beside a 0.3 m strip, up half its 20 m length, the capture point at the
  // other end): its band is most of its influence, and one of its ends comes in past the band,
  // as few steps as get under the target, or as cut the share most. The floor it leaves is in
  // its neighbours' bands, or the uncovered floor's fills'. A range wider than the gap keeps
  // its floor: its own proxy serves that floor better than a neighbour's band (runningman: a
  // fill cut by 6 m of its 16, 0.7 points more of the floor over 5 deg).
  const glm::dvec3 size = hi - lo;
  const bool strip = std::min(size.x, size.y) < gapMeters;
  const auto stepsToCapture = [&](int side) {
    const int axis = side / 2;
    const double room = side % 2 == 0 ? capture[axis] - kCaptureMarginMeters - innerLo[axis]
                                      : innerHi[axis] - capture[axis] - kCaptureMarginMeters;
    return static_cast<int>(std::ceil(room / step));
  };
  while (strip && share > kLeakShareTarget) {
    int bestSide = -1, bestSteps = 0;
    double bestShare = share;
    for (int side = 0; side < 4; ++side) {
      for (int k = steps[side] + 1; k <= stepsToCapture(side); ++k) {
        const double s = shareIfPulled(side, k);
        if (s > kLeakShareTarget) continue;
        if (bestShare > kLeakShareTarget || k - steps[side] < bestSteps - steps[bestSide])
          bestShare = s, bestSide = side, bestSteps = k;
        break;
      }
    }
    if (bestSide < 0)
      for (int side = 0; side < 4; ++side)
        pullFurthest(side, stepsToCapture(side), bestSide, bestSteps, bestShare);
    if (bestSide < 0) break;
    steps[bestSide] = bestSteps;
    pulled(bestSide, bestSteps, lo, hi);
    share = bestShare;
  }
  innerLo = lo;
  innerHi = hi;
}

}  // namespace probeproxy
