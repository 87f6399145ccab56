#include "geometry/layout/floor_rectangles.h"

#include "geometry/survey/blended_error.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace probeproxy {

namespace {

// In the rectangle's columns and rows, from `belowMeters` under its floor to head room over it.
bool inWindow(const FloorRect& r, const FloorCell& cell, double belowMeters) {
  const double z = cell.pointMeters.z;
  return cell.column >= r.column0 && cell.column <= r.column1 && cell.row >= r.row0 &&
         cell.row <= r.row1 && z >= r.floorMeters - belowMeters &&
         z <= r.floorMeters + kInfluenceHeadRoomMeters;
}

}  // namespace

bool FloorRect::holds(const FloorCell& cell) const {
  return inWindow(*this, cell, kInfluenceBelowFloorMeters);
}

bool FloorRect::underInnerRange(const FloorCell& cell) const {
  // The survey lifts each sample kBlendLiftMeters before it asks which ranges hold it: floor a
  // hair more than a step under the range is in it as the survey sees it, and a fill grown there
  // would overlap the range (warfare: a fill 0.51 m under its neighbour's floor).
  return inWindow(*this, cell,
                  kInfluenceBelowFloorMeters + kInfluenceStepMeters + kBlendLiftMeters);
}

FloorColumns::FloorColumns(const WalkableFloor& floor)
    : floor_(&floor),
      first_(static_cast<std::size_t>(floor.columns) * floor.rows, 0),
      count_(first_.size(), 0) {
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    const std::size_t k =
        static_cast<std::size_t>(floor.cells[i].row) * floor.columns + floor.cells[i].column;
    if (count_[k]++ == 0) first_[k] = i;  // cells come by row, column, then height
  }
}

void FloorColumns::forEachIn(const FloorRect& rect, int column, int row,
                             const std::function<void(std::size_t)>& f) const {
  if (column < 0 || row < 0 || column >= floor_->columns || row >= floor_->rows) return;
  const std::size_t k = static_cast<std::size_t>(row) * floor_->columns + column;
  for (std::size_t i = first_[k]; i < first_[k] + count_[k]; ++i)
    if (rect.holds(floor_->cells[i])) f(i);
}

void FloorColumns::forEachIn(const FloorRect& rect,
                             const std::function<void(std::size_t)>& f) const {
  for (int r = rect.row0; r <= rect.row1; ++r)
    for (int c = rect.column0; c <= rect.column1; ++c) forEachIn(rect, c, r, f);
}

void FloorColumns::forEachInPlan(const FloorRect& rect,
                                 const std::function<void(std::size_t)>& f) const {
  for (int r = std::max(rect.row0, 0); r <= std::min(rect.row1, floor_->rows - 1); ++r) {
    for (int c = std::max(rect.column0, 0); c <= std::min(rect.column1, floor_->columns - 1); ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * floor_->columns + c;
      for (std::size_t i = first_[k]; i < first_[k] + count_[k]; ++i) f(i);
    }
  }
}

void FloorColumns::forEachUnderInnerRange(const FloorRect& rect,
                                          const std::function<void(std::size_t)>& f) const {
  forEachInPlan(rect, [&](std::size_t i) {
    if (rect.underInnerRange(floor_->cells[i])) f(i);
  });
}

std::size_t middleCell(const FloorColumns& columns, const FloorRect& rect) {
  const double column = 0.5 * (rect.column0 + rect.column1), row = 0.5 * (rect.row0 + rect.row1);
  std::size_t best = columns.floor().cells.size();
  double nearest = std::numeric_limits<double>::infinity();
  columns.forEachIn(rect, [&](std::size_t i) {
    const FloorCell& c = columns.floor().cells[i];
    const double d = (c.column - column) * (c.column - column) + (c.row - row) * (c.row - row);
    if (d < nearest) nearest = d, best = i;
  });
  return best;
}

FloorRect widened(const FloorRect& rect, int cells) {
  FloorRect w = rect;
  w.column0 -= cells, w.column1 += cells, w.row0 -= cells, w.row1 += cells;
  return w;
}

FloorRect growFloorRect(const FloorColumns& columns, std::size_t startCell,
                        const std::function<double(std::size_t)>& acceptable,
                        const std::function<bool(std::size_t)>& claimed, double acceptedShare) {
  const FloorCell& start = columns.floor().cells[startCell];
  if (claimed(startCell)) return FloorRect{};
  return grownFloorRect(
      columns, FloorRect{start.column, start.column, start.row, start.row, start.pointMeters.z},
      acceptable, claimed, acceptedShare);
}

FloorRect grownFloorRect(const FloorColumns& columns, FloorRect rect,
                         const std::function<double(std::size_t)>& acceptable,
                         const std::function<bool(std::size_t)>& claimed, double acceptedShare) {
  // The strip one past a side: the new rectangle minus the old one.
  const auto tryGrow = [&](int side) {
    FloorRect next = rect;
    if (side == 0) --next.column0;
    if (side == 1) ++next.column1;
    if (side == 2) --next.row0;
    if (side == 3) ++next.row1;
    FloorRect strip = next;
    if (side == 0) strip.column1 = next.column0;
    if (side == 1) strip.column0 = next.column1;
    if (side == 2) strip.row1 = next.row0;
    if (side == 3) strip.row0 = next.row1;
    double area = 0.0, acceptedArea = 0.0;
    bool blocked = false;
    columns.forEachIn(strip, [&](std::size_t i) {
      if (claimed(i)) blocked = true;
      const double a = columns.floor().cells[i].areaSquareMeters;
      area += a;
      acceptedArea += a * acceptable(i);
    });
    if (blocked || area <= 0.0 || acceptedArea < acceptedShare * area) return false;
    rect = next;
    return true;
  };
  std::array<bool, 4> open{true, true, true, true};
  for (bool grew = true; grew;) {
    grew = false;
    for (int side = 0; side < 4; ++side)
      if (open[side]) grew |= (open[side] = tryGrow(side));
  }
  return rect;
}

void floorRectBounds(const WalkableFloor& floor, const FloorRect& rect, glm::dvec3 captureMeters,
                     glm::dvec3& lo, glm::dvec3& hi) {
  const double s = floor.spacingMeters;
  lo = {floor.originMeters.x + rect.column0 * s, floor.originMeters.y + rect.row0 * s,
        rect.floorMeters - kInfluenceBelowFloorMeters - kInfluenceStepMeters};
  hi = {floor.originMeters.x + (rect.column1 + 1) * s, floor.originMeters.y + (rect.row1 + 1) * s,
        rect.floorMeters + kInfluenceHeadRoomMeters};
  lo = glm::min(lo, captureMeters - glm::dvec3(kCaptureMarginMeters));
  hi = glm::max(hi, captureMeters + glm::dvec3(kCaptureMarginMeters));
}

}  // namespace probeproxy
