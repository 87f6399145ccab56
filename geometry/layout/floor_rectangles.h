#pragma once
// The floor as Lagarde's blend shades it with box influences: inside a box's inner range its
// probe takes 100% whatever else overlaps there, so a layout's inner ranges partition the floor,
// and each must hold only floor its probe serves. This file grows such ranges: rectangles of
// floor cells (one storey's height window each) from a capture point's cell, a row or column at
// a time, while the new strip is floor the probe may shade and no other range has claimed.
// Claimed floor reaches a gap past each chosen range, so neighbours' inner ranges never touch:
// the gap is where the outer ranges blend, and the weights stay continuous.

#include "geometry/floor/walkable_floor.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace probeproxy {

inline constexpr double kInfluenceBelowFloorMeters = 0.25;
inline constexpr double kInfluenceHeadRoomMeters = 2.5;
// The inner range reaches this much further down than the cells it holds: the survey's finer
// floor has points on a stair's steps between the layout's cells, up to a step (0.45 m) under
// the lowest cell (darkzone's stairs were left in no volume); the vertical band
// (layout_influence.h) gives the rest.
inline constexpr double kInfluenceStepMeters = 0.25;
// An inner range holds its capture point at least this far inside.
inline constexpr double kCaptureMarginMeters = 0.05;

struct FloorRect {
  int column0 = 0, column1 = -1, row0 = 0, row1 = -1;  // inclusive cell ranges
  double floorMeters = 0.0;  // the storey: cells from this - below to this + head room
  bool empty() const { return column1 < column0 || row1 < row0; }
  // Whether a floor cell lies inside (its column and row in range, its height in the window).
  bool holds(const FloorCell& cell) const;
  // Whether a floor cell lies under the inner range of the rectangle's influence box
  // (floorRectBounds) as the survey sees it: as holds, and down to a step under the window.
  bool underInnerRange(const FloorCell& cell) const;
};

// The cells of each grid column, for the strips' lookups.
class FloorColumns {
 public:
  explicit FloorColumns(const WalkableFloor& floor);
  const WalkableFloor& floor() const { return *floor_; }
  // Calls f(cell index) for every cell of column (c, r) in the rectangle's height window.
  void forEachIn(const FloorRect& rect, int column, int row,
                 const std::function<void(std::size_t)>& f) const;
  void forEachIn(const FloorRect& rect, const std::function<void(std::size_t)>& f) const;
  // Calls f(cell index) for every cell of the rectangle's columns, at any height.
  void forEachInPlan(const FloorRect& rect, const std::function<void(std::size_t)>& f) const;
  // Calls f(cell index) for every cell under the rectangle's inner range (underInnerRange).
  void forEachUnderInnerRange(const FloorRect& rect,
                              const std::function<void(std::size_t)>& f) const;

 private:
  const WalkableFloor* floor_;
  std::vector<std::size_t> first_, count_;  // per grid column (row * columns + column)
};

// `acceptable(cell)`: how far the probe may shade it, 0 to 1 (a strip grows the rectangle when
// its area-weighted mean is at least `acceptedShare`); `claimed(cell)`: another range's. A strip
// holding no floor at all ends the growth that way (a room's edge), as does one holding a claimed
// cell. Sides grow in turn (-x, +x, -y, +y) until none can. Empty when the start cell is claimed.
FloorRect growFloorRect(const FloorColumns& columns, std::size_t startCell,
                        const std::function<double(std::size_t)>& acceptable,
                        const std::function<bool(std::size_t)>& claimed, double acceptedShare);

// The same growth from a rectangle already grown.
FloorRect grownFloorRect(const FloorColumns& columns, FloorRect rect,
                         const std::function<double(std::size_t)>& acceptable,
                         const std::function<bool(std::size_t)>& claimed, double acceptedShare);

// The rectangle's cell nearest its middle (in plan). The rectangle must hold a cell.
std::size_t middleCell(const FloorColumns& columns, const FloorRect& rect);

// The rectangle widened by `cells` on every side (the gap a neighbour keeps from it).
FloorRect widened(const FloorRect& rect, int cells);

// Its inner range in world metres: the cells' plan area, from a step under the storey's floor
// to head room over it, stretched to hold the capture point.
void floorRectBounds(const WalkableFloor& floor, const FloorRect& rect, glm::dvec3 captureMeters,
                     glm::dvec3& lo, glm::dvec3& hi);

}  // namespace probeproxy
