#include "geometry/layout/layout_candidates.h"

#include "geometry/layout/floor_rectangles.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/open_space.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

glm::dvec3 captureAbove(const LevelRayCaster& level, glm::dvec3 floorMeters, double heightMeters) {
  Ray up;
  up.originMeters = floorMeters + glm::dvec3(0.0, 0.0, 1e-3);
  up.direction = {0.0f, 0.0f, 1.0f};
  up.tMax = static_cast<float>(2.0 * heightMeters);
  const RayHit hit = level.firstHit(up);
  const double freeHeight = hit.hit() ? hit.t : 2.0 * heightMeters;
  return floorMeters + glm::dvec3(0.0, 0.0, std::min(heightMeters, 0.5 * freeHeight));
}

namespace {

// Whether a capture point moved `offset` off its cell's centre stands on the open side of
// whatever lies between: a ray back to the centre's column that first meets a face from behind
// starts inside a solid (a wall a cell's centre lies in the face of, entered a quarter cell).
bool onOpenSide(const LevelRayCaster& level, glm::dvec3 capture, glm::dvec3 offset) {
  const double length = glm::length(offset);
  if (length <= 0.0) return true;
  Ray back;
  back.originMeters = capture;
  back.direction = glm::vec3(-offset / length);
  back.tMax = static_cast<float>(length);
  const RayHit hit = level.firstHit(back);
  return !hit.hit() || glm::dot(back.direction, hit.geometricNormal) < 0.0f;
}

}  // namespace

ClearCapture clearCaptureAbove(const LevelRayCaster& level, const WalkableFloor& floor,
                               std::span<const std::size_t> cells, double heightMeters) {
  ClearCapture best;
  // Over the cells' centres first, then, only when none may hold a probe, a quarter cell off
  // them each way: one cell of floor between a wall and a pillar (warfare's fills) has its
  // centre in a face.
  const double q = 0.25 * floor.spacingMeters;
  const glm::dvec3 offsets[] = {{0, 0, 0}, {q, 0, 0},  {-q, 0, 0}, {0, q, 0},  {0, -q, 0},
                                {q, q, 0}, {-q, q, 0}, {q, -q, 0}, {-q, -q, 0}};
  for (const glm::dvec3& offset : offsets) {
    if (best.clearanceMeters >= kMinCaptureClearanceMeters) break;
    for (std::size_t c : cells) {
      const glm::dvec3 capture =
          captureAbove(level, floor.cells[c].pointMeters + offset, heightMeters);
      if (!onOpenSide(level, capture, offset)) continue;
      const double clearance = nearestSurface(level, capture).distanceMeters;
      if (clearance > best.clearanceMeters) best = {capture, clearance};
      if (clearance >= kLayoutCaptureClearanceMeters) return best;
    }
  }
  return best;
}

bool clearMovedCapture(const LevelRayCaster& level, glm::dvec3 chosenMeters,
                       glm::dvec3& captureMeters, double floorMeters, double topMeters) {
  if (captureMeters == chosenMeters) return true;
  // A ramp or a stair in the range stands higher than the range's floor under the chosen point.
  const float chosenOver = lookUpAndDown(level, std::span(&chosenMeters, 1))[0].floorBelowMeters;
  const double base =
      std::isfinite(chosenOver) ? std::max(floorMeters, chosenMeters.z - chosenOver) : floorMeters;
  std::vector<glm::dvec3> heights;
  for (double up : {0.5, 0.375, 0.625, 0.25, 0.75})
    heights.push_back({captureMeters.x, captureMeters.y, base + up * (topMeters - base)});
  // Over a floor, not inside a solid nor under a one-sided ramp (open_space.h: outside the
  // level, where darkzone's fill saw none of its floor).
  const std::vector<VerticalView> views = lookUpAndDown(level, heights);
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if (!std::isfinite(views[i].floorBelowMeters) ||
        nearestSurface(level, heights[i]).distanceMeters < kLayoutCaptureClearanceMeters)
      continue;
    captureMeters = heights[i];
    return true;
  }
  return false;
}

std::vector<std::size_t> nearestFirst(const WalkableFloor& floor, std::vector<std::size_t> cells,
                                      glm::dvec3 middleMeters) {
  const auto planDistance = [&](std::size_t c) {
    const glm::dvec3 d = floor.cells[c].pointMeters - middleMeters;
    return d.x * d.x + d.y * d.y;
  };
  std::stable_sort(cells.begin(), cells.end(),
                   [&](std::size_t a, std::size_t b) { return planDistance(a) < planDistance(b); });
  return cells;
}

LayoutCandidates layoutCandidates(const LevelRayCaster& level, const WalkableFloor& floor,
                                  double spacingMeters, double captureHeightMeters,
                                  std::size_t maxCandidates) {
  // Every step-th column and row, offset by half a step so a room's first candidate stands off
  // its wall.
  int step = std::max(1, static_cast<int>(std::lround(spacingMeters / floor.spacingMeters)));
  const auto onGrid = [&](const FloorCell& cell) {
    return cell.column % step == step / 2 && cell.row % step == step / 2;
  };
  while (std::count_if(floor.cells.begin(), floor.cells.end(), onGrid) >
         static_cast<std::ptrdiff_t>(maxCandidates))
    ++step;
  LayoutCandidates candidates;
  candidates.spacingMeters = step * floor.spacingMeters;
  const auto tryCell = [&](std::size_t i) {
    const glm::dvec3 capture = captureAbove(level, floor.cells[i].pointMeters, captureHeightMeters);
    // A point in a wall's face or a thin prop would capture the level from behind it.
    if (nearestSurface(level, capture).distanceMeters < kLayoutCaptureClearanceMeters) return;
    candidates.points.push_back({capture, i});
  };
  for (std::size_t i = 0; i < floor.cells.size(); ++i)
    if (onGrid(floor.cells[i])) tryCell(i);
  // Floor the grid passes by (a closet narrower than the spacing, a corridor between its
  // columns) gets a point of its own: every cell has a candidate within a step on its storey.
  const FloorColumns columns(floor);
  std::vector<char> near(floor.cells.size(), 0);
  const auto markAround = [&](const LayoutCandidate& c) {
    const FloorCell& at = floor.cells[c.cell];
    FloorRect window{at.column - step, at.column + step, at.row - step, at.row + step,
                     at.pointMeters.z};
    columns.forEachIn(window, [&](std::size_t cell) { near[cell] = 1; });
  };
  for (const LayoutCandidate& c : candidates.points) markAround(c);
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    if (near[i]) continue;
    const std::size_t before = candidates.points.size();
    tryCell(i);
    if (candidates.points.size() > before) markAround(candidates.points.back());
    near[i] = 1;
  }
  return candidates;
}

}  // namespace probeproxy
