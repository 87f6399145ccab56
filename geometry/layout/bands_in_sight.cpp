#include "geometry/layout/bands_in_sight.h"

#include "core/blend/influence_factor.h"
#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/raycast/room_in_sight.h"
#include "geometry/survey/blended_error.h"

#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
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
  while (share > kLeakShareTarget) {
    int bestSide = -1, bestSteps = 0;
    double bestShare = share;
    for (int side = 0; side < 4; ++side) {
      for (int k = steps[side] + 1; k <= maxSteps; ++k) {
        glm::dvec3 l, h;
        pulled(side, k, l, h);
        const double s = hiddenShare(inBox, l, h, gapMeters);
        if (s < bestShare) bestShare = s, bestSide = side, bestSteps = k;
      }
    }
    if (bestSide < 0) break;  // floor out of sight under the inner range, or by the capture
    steps[bestSide] = bestSteps;
    pulled(bestSide, bestSteps, lo, hi);
    share = bestShare;
  }
  innerLo = lo;
  innerHi = hi;
}

}  // namespace probeproxy
