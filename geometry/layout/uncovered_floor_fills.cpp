#include "geometry/layout/uncovered_floor_fills.h"

#include "core/blend/blend_weights.h"
#include "core/blend/influence_factor.h"
#include "geometry/layout/bands_in_sight.h"
#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/survey/blended_error.h"
#include "geometry/validate/camera_space.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace probeproxy {

namespace {

// Floor further out than this share of every band over it is served by bands' far ends alone:
// their weights are all near 0 there, and where one more band begins its normalised share
// jumps (validate's weight_jump, 0.1-0.3 per cm over such floor on basement and darkzone).
// The selection keeps floor within a gap of a range (at most 5/6 of a band out); two thirds
// keeps the steepest turn of the weights under validate's limit.
constexpr double kFarBandShare = 0.67;

// Rounds of fills over floor the fills before them left uncovered (each a fill cut back by a
// range beside it), at most: a round that makes no fill ends them.
constexpr std::size_t kMaxCoverRounds = 4;

// Where a camera stands over a floor cell: its eye, and the top of validate's camera space
// (head room, 2.5 m: eye height and a jump), just under it.
constexpr std::array<double, 2> kCameraLiftsMeters{1.6, kInfluenceHeadRoomMeters - 0.05};

// Whether the range keeps the gap in plan from every inner range beside its heights: cut back
// only to its capture point (keepClearOfInnerRanges), a fill over a range's top 8 cm from a
// range beside it handed the whole weight over within those 8 cm (skyway: 0.11 per cm). (The
// far-band fills keep theirs: without them toxic's p95 is 0.3 deg worse.)
bool keepsTheGapBeside(const InnerRange& range, std::span<const InfluenceVolume> others,
                       double gapMeters) {
  for (const InfluenceVolume& v : others) {
    const std::optional<InnerRange> other = innerRangeOf(v);
    if (other && overlapInHeight(range, *other) &&
        planApart(range, *other) < gapMeters - kInnerClearanceMeters)
      return false;
  }
  return true;
}

// Plan distance from a point to a rectangle (0 inside).
double planDistance(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi) {
  const double dx = std::max({0.0, lo.x - p.x, p.x - hi.x});
  const double dy = std::max({0.0, lo.y - p.y, p.y - hi.y});
  return std::hypot(dx, dy);
}

// The nearest any volume's band is at `p` (0 in an inner range, 1 outside them all).
double nearestBand(std::span<const InfluenceVolume> volumes, glm::dvec3 p) {
  double nearest = 1.0;
  for (const InfluenceVolume& v : volumes) nearest = std::min(nearest, normalizedDistance(v, p));
  return nearest;
}

// The same where the blend weighs a floor cell: kBlendLiftMeters over it, as the survey does.
double nearestBandOver(std::span<const InfluenceVolume> volumes, const FloorCell& cell) {
  return nearestBand(volumes, cell.pointMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters));
}

// The highest top of the inner ranges holding `p`; -inf when none does.
double topOfRangesHolding(std::span<const InfluenceVolume> volumes, glm::dvec3 p) {
  double top = -INFINITY;
  for (const InfluenceVolume& v : volumes)
    if (const std::optional<InnerRange> r = innerRangeOf(v); r && holds(*r, p))
      top = std::max(top, r->hi.z);
  return top;
}

// The corners of the box round the cells' points.
std::pair<glm::dvec3, glm::dvec3> cellBounds(const WalkableFloor& floor,
                                             std::span<const std::size_t> cells) {
  glm::dvec3 lo = floor.cells[cells.front()].pointMeters, hi = lo;
  for (std::size_t c : cells) {
    lo = glm::min(lo, floor.cells[c].pointMeters);
    hi = glm::max(hi, floor.cells[c].pointMeters);
  }
  return {lo, hi};
}

struct FillContext {
  const LevelRayCaster& level;
  const WalkableFloor& floor;
  std::span<const char> covered;
  double gapMeters, captureHeightMeters;
  bool aboveRanges;  // as fillGroups'
};

// The fill of one group of cells (its first cell's height is its storey's floor), kept clear
// of `others` and then added to them. None where no capture point stands clear of the level
// and of the inner ranges beside, nor for an optional fill whose band needs pulling or one too
// near a range beside.
void fillGroup(const FillContext& c, std::span<const std::size_t> members,
               std::vector<InfluenceVolume>& others, std::vector<FloorFill>& fills) {
  const WalkableFloor& floor = c.floor;
  const double half = 0.5 * floor.spacingMeters;
  const double storeyFloor = floor.cells[members.front()].pointMeters.z;
  const auto [lo, hi] = cellBounds(floor, members);
  glm::dvec3 innerLo(lo.x - half, lo.y - half,
                     lo.z - kInfluenceBelowFloorMeters - kInfluenceStepMeters);
  double captureHeight = c.captureHeightMeters;
  if (c.aboveRanges) {
    for (std::size_t m : members) {
      const glm::dvec3 over = floor.cells[m].pointMeters + glm::dvec3(0, 0, kBlendLiftMeters);
      innerLo.z = std::max(innerLo.z, topOfRangesHolding(others, over) + kInnerClearanceMeters);
    }
    // Half way up what is left of head room over the floor, when that is higher.
    captureHeight =
        std::max(captureHeight, 0.5 * (innerLo.z + hi.z + kInfluenceHeadRoomMeters) - lo.z);
  }
  const ClearCapture clear = clearCaptureAbove(
      c.level, floor,
      nearestFirst(floor, std::vector<std::size_t>(members.begin(), members.end()),
                   0.5 * (lo + hi)),
      captureHeight);
  // A scene may not hold a probe in a surface (checkCapturePoints); no room over that top.
  glm::dvec3 capture = clear.captureMeters;
  if (clear.clearanceMeters < kMinCaptureClearanceMeters ||
      capture.z < innerLo.z + kCaptureMarginMeters)
    return;
  glm::dvec3 innerHi(hi.x + half, hi.y + half, hi.z + kInfluenceHeadRoomMeters);
  innerLo = glm::min(innerLo, capture - glm::dvec3(kCaptureMarginMeters));
  innerHi = glm::max(innerHi, capture + glm::dvec3(kCaptureMarginMeters));
  const glm::dvec3 chosen = capture;
  keepClearOfInnerRanges(innerLo, innerHi, capture, storeyFloor, others, c.gapMeters,
                         StripForHeadRoom::atMostAQuarterOrLeavingAGap);
  if (!clearMovedCapture(c.level, chosen, capture, storeyFloor, innerHi.z)) return;
  // A range above came down to the fill's bottom (over a range's top) or under its capture
  // point: nothing left to fill (stormkeep: 0 m and -1 mm tall).
  if (!glm::all(glm::lessThan(innerLo, innerHi)) ||
      !glm::all(glm::lessThanEqual(innerLo, capture)) ||
      !glm::all(glm::lessThanEqual(capture, innerHi)))
    return;
  const glm::dvec3 clearLo = innerLo, clearHi = innerHi;
  pullBandsIntoSight(c.level, floor, capture, c.gapMeters, innerLo, innerHi);
  const BoxInfluence fill = influenceOfBounds(innerLo, innerHi, c.gapMeters);
  // A fill over covered floor is worth less than a band through a wall (the pull leaves up
  // to validate's limit behind it: downer, 6.4% measured at other heights), and than a crowd
  // of bands the trim cannot free (run_layout drops it then).
  const bool optional =
      std::all_of(members.begin(), members.end(), [&](std::size_t m) { return c.covered[m] != 0; });
  if (optional && (innerLo != clearLo || innerHi != clearHi)) return;
  if (c.aboveRanges && !keepsTheGapBeside({innerLo, innerHi}, others, c.gapMeters)) return;
  fills.push_back({capture, fill, optional});
  others.push_back(fills.back().influence);
}

// One fill per group of `toFill` (cells within a gap of one another on one storey), each kept
// clear of `others` and then added to them. `aboveRanges`: the cells' floor lies in an inner
// range whose top is under head room over it (a ramp's range stopped under a range above,
// head_room.h), so the fill starts over that top, where the cameras it serves stand.
// A group's cells that an earlier group's fill holds in its inner range are not filled again:
// a group's storey is its first cell's, and floor a hair past the storey's reach below
// (runningman: 749 cells 0.25 m under the first) made a second group whose fill stood over
// the first's floor, its capture point inside the first's plan, where keepClearOfInnerRanges
// cannot part them (inner ranges overlapping by 239 m^3). They still join the group: left out
// of the grouping, they split the groups around them into slivers (bleach: 7 fills more, some
// 0.25 m wide). Only floor an inner range holds: floor in a fill's band alone is filled
// (skipping floor within two thirds of a band, as the selection keeps it, cost bleach 0.25 deg
// of p95).
void fillGroups(const LevelRayCaster& level, const WalkableFloor& floor,
                std::span<const std::size_t> toFill, std::span<const char> covered,
                double gapMeters, double captureHeightMeters, bool aboveRanges,
                std::vector<InfluenceVolume>& others, std::vector<FloorFill>& fills) {
  const FillContext context{level, floor, covered, gapMeters, captureHeightMeters, aboveRanges};
  const std::size_t before = others.size();
  const auto heldByAnEarlierFill = [&](std::size_t cell) {
    return nearestBandOver(std::span(others).subspan(before), floor.cells[cell]) == 0.0;
  };
  std::vector<char> grouped(toFill.size(), 0);
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
    std::erase_if(members, heldByAnEarlierFill);
    if (!members.empty()) fillGroup(context, members, others, fills);
  }
}

}  // namespace

std::vector<FloorFill> fillsForUncoveredFloor(const LevelRayCaster& level,
                                              const WalkableFloor& floor,
                                              std::span<const InfluenceVolume> volumes,
                                              double gapMeters, double captureHeightMeters) {
  std::vector<std::size_t> toFill;
  std::vector<char> covered(floor.cells.size(), 0);
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    const double nearest = nearestBandOver(volumes, floor.cells[i]);
    covered[i] = nearest < 1.0;
    if (nearest > kFarBandShare) toFill.push_back(i);
  }
  std::vector<InfluenceVolume> others(volumes.begin(), volumes.end());
  std::vector<FloorFill> fills;
  fillGroups(level, floor, toFill, covered, gapMeters, captureHeightMeters, false, others, fills);
  // A fill cut back to keep clear of a range beside it (keepClearOfInnerRanges) serves part of
  // its group: what no volume covers yet is grouped and filled again, until a round makes no
  // fill (desertfactory: a 30 m strip under an overhang, 0.11% of its floor, beside the one
  // fill its group got).
  for (std::size_t made = fills.size(), round = 0; round < kMaxCoverRounds; ++round) {
    toFill.clear();
    for (std::size_t i = 0; i < floor.cells.size(); ++i)
      if (nearestBandOver(others, floor.cells[i]) >= 1.0) toFill.push_back(i);
    if (toFill.empty()) break;
    fillGroups(level, floor, toFill, covered, gapMeters, captureHeightMeters, false, others, fills);
    if (fills.size() == made) break;
    made = fills.size();
  }
  // Then where a camera's eye over the floor is reached only by the far ends of bands (over a
  // ramp whose range stops under a range above it: warfare, stormkeep, bloodprison), where
  // the eye is open space over that floor.
  std::vector<std::size_t> eyeCells;
  std::vector<glm::dvec3> eyes;
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    for (double lift : kCameraLiftsMeters) {
      const glm::dvec3 eye = floor.cells[i].pointMeters + glm::dvec3(0.0, 0.0, lift);
      if (nearestBand(others, eye) <= kFarBandShare) continue;
      eyeCells.push_back(i), eyes.push_back(eye);
      break;
    }
  }
  std::vector<char> open(eyes.size(), 0);
  markCameraSpace(level, floor, kInfluenceHeadRoomMeters, eyes, open);
  toFill.clear();
  for (std::size_t e = 0; e < eyeCells.size(); ++e)
    if (open[e]) toFill.push_back(eyeCells[e]);
  fillGroups(level, floor, toFill, covered, gapMeters, captureHeightMeters, true, others, fills);
  return fills;
}

}  // namespace probeproxy
