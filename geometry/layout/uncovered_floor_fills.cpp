#include "geometry/layout/uncovered_floor_fills.h"

#include "core/blend/blend_weights.h"
#include "core/blend/influence_factor.h"
#include "geometry/layout/bands_in_sight.h"
#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/survey/blended_error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

// Floor further out than this share of every band over it is served by bands' far ends alone:
// their weights are all near 0 there, and where one more band begins its normalised share
// jumps (validate's weight_jump, 0.1-0.3 per cm over such floor on basement and darkzone).
// The selection keeps floor within a gap of a range (at most 5/6 of a band out); two thirds
// keeps the steepest turn of the weights under validate's limit.
constexpr double kFarBandShare = 0.67;

// Where a camera stands over a floor cell (its eye), for the overlap count.
constexpr double kEyeOverFloorMeters = 1.6;

// Whether adding `fill` makes more volumes than the blend takes (Lagarde's 4) meet at a camera
// over the floor under its outer range, outside every inner range (validate's
// too_many_overlaps): a fill for floor already covered is worth less than that.
bool crowdsTheBlend(const BoxInfluence& fill, std::span<const InfluenceVolume> others,
                    const WalkableFloor& floor) {
  for (const FloorCell& cell : floor.cells) {
    for (double lift : {kBlendLiftMeters, kEyeOverFloorMeters}) {
      const glm::dvec3 p = cell.pointMeters + glm::dvec3(0.0, 0.0, lift);
      if (!insideInfluence(fill, p) || normalizedDistance(fill, p) == 0.0) continue;
      int meeting = 1;
      bool inner = false;
      for (const InfluenceVolume& v : others) {
        const double a = normalizedDistance(v, p);
        inner = inner || a == 0.0;
        meeting += a < 1.0;
      }
      if (!inner && meeting > kDefaultMaxBlendProbes) return true;
    }
  }
  return false;
}

// Plan distance from a point to a rectangle (0 inside).
double planDistance(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi) {
  const double dx = std::max({0.0, lo.x - p.x, p.x - hi.x});
  const double dy = std::max({0.0, lo.y - p.y, p.y - hi.y});
  return std::hypot(dx, dy);
}

}  // namespace

std::vector<FloorFill> fillsForUncoveredFloor(const LevelRayCaster& level,
                                              const WalkableFloor& floor,
                                              std::span<const InfluenceVolume> volumes,
                                              double gapMeters, double captureHeightMeters) {
  std::vector<std::size_t> toFill;
  std::vector<char> covered(floor.cells.size(), 0);
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    const glm::dvec3 at = floor.cells[i].pointMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters);
    double nearest = 1.0;
    for (const InfluenceVolume& v : volumes) nearest = std::min(nearest, normalizedDistance(v, at));
    covered[i] = nearest < 1.0;
    if (nearest > kFarBandShare) toFill.push_back(i);
  }
  const double half = 0.5 * floor.spacingMeters;
  std::vector<InfluenceVolume> others(volumes.begin(), volumes.end());
  std::vector<char> grouped(toFill.size(), 0);
  std::vector<FloorFill> fills;
  for (std::size_t first = 0; first < toFill.size(); ++first) {
    if (grouped[first]) continue;
    grouped[first] = 1;
    const glm::dvec3 start = floor.cells[toFill[first]].pointMeters;
    const double storeyFloor = start.z;
    glm::dvec3 lo = start, hi = start;
    std::vector<std::size_t> members{toFill[first]};
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t k = first + 1; k < toFill.size(); ++k) {
        const glm::dvec3 p = floor.cells[toFill[k]].pointMeters;
        if (grouped[k] || p.z < storeyFloor - kInfluenceBelowFloorMeters ||
            p.z > storeyFloor + kInfluenceHeadRoomMeters ||
            planDistance(p, lo, hi) > gapMeters + floor.spacingMeters)
          continue;
        grouped[k] = 1, grew = true;
        members.push_back(toFill[k]);
        lo = glm::min(lo, p), hi = glm::max(hi, p);
      }
    }
    glm::dvec3 capture =
        clearCaptureAbove(level, floor, nearestFirst(floor, members, 0.5 * (lo + hi)),
                          captureHeightMeters)
            .captureMeters;
    glm::dvec3 innerLo(lo.x - half, lo.y - half,
                       lo.z - kInfluenceBelowFloorMeters - kInfluenceStepMeters);
    glm::dvec3 innerHi(hi.x + half, hi.y + half, hi.z + kInfluenceHeadRoomMeters);
    innerLo = glm::min(innerLo, capture - glm::dvec3(kCaptureMarginMeters));
    innerHi = glm::max(innerHi, capture + glm::dvec3(kCaptureMarginMeters));
    keepClearOfInnerRanges(innerLo, innerHi, capture, storeyFloor, others, gapMeters);
    const glm::dvec3 clearLo = innerLo, clearHi = innerHi;
    pullBandsIntoSight(level, floor, capture, gapMeters, innerLo, innerHi);
    const BoxInfluence fill = influenceOfBounds(innerLo, innerHi, gapMeters);
    // A fill over covered floor is worth less than a band through a wall (the pull leaves up
    // to validate's limit behind it: downer, 6.4% measured at other heights), and than a crowd
    // the bands' trim cannot free (run_layout drops it then).
    const bool optional =
        std::all_of(members.begin(), members.end(), [&](std::size_t c) { return covered[c] != 0; });
    if (optional && (innerLo != clearLo || innerHi != clearHi)) continue;
    fills.push_back({capture, fill, optional && crowdsTheBlend(fill, others, floor)});
    others.push_back(fills.back().influence);
  }
  return fills;
}

}  // namespace probeproxy
