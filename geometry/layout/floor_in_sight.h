#pragma once
// Which floor cells each candidate capture point holds in sight (geometry/raycast/
// room_in_sight.h, validate's influence_leak test): a probe's inner range holds only such
// floor, so no volume lights a room its probe has never seen. A candidate serves floor by its
// reflections (capture_sight.h), and a reflection off floor behind a wall can land on a
// ceiling both sides see: served, yet the leak rule's. Asked lazily (the selection asks only
// about the cells a capture point sees and its rectangles grow over, a small part of the level
// for each of a thousand capture points) and cached in blocks made on first use, a block the
// cells of a square of the plan: the cache grows with the floor each capture point is asked
// about, not with capture points times the level (blocks of cells in index order, a row each
// on an open level, made a capture point that sees down a street hold every row it crosses).
// The answer does not depend on who asks first, so the selection stays the same whatever the
// thread count.

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/raycast/room_in_sight.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace probeproxy {

class FloorInSight {
 public:
  FloorInSight(const LevelRayCaster& level, const WalkableFloor& floor,
               std::span<const glm::dvec3> capturesMeters);
  ~FloorInSight();
  FloorInSight(const FloorInSight&) = delete;
  FloorInSight& operator=(const FloorInSight&) = delete;

  // The cache's blocks: the cells of kBlockColumns x kBlockColumns grid columns, a byte each.
  static constexpr int kBlockColumns = 32;

  bool inSight(std::size_t capture, std::size_t cell) const;
  // The same answer, from the cache when it holds it, else asked of the level and not kept:
  // for a pass over everything a capture point sees, once.
  bool inSightOnce(std::size_t capture, std::size_t cell) const;

 private:
  const LevelRayCaster* level_;
  std::size_t cellCount_;
  std::vector<RoomTargets> targets_;                 // per cell: roomTargetsOver its point
  std::vector<std::vector<glm::dvec3>> viewpoints_;  // per capture: roomViewpoints
  // [capture * blocks + blockOf_[cell]][slotOf_[cell]]: 0 not asked yet, else kInSight or
  // kHidden; a block is made by the first thread that asks about one of its cells.
  using Block = std::atomic<std::uint8_t>;  // the first of the block's cells
  // A cell's answer in the cache; its block made when `make`, else nullptr without it.
  std::atomic<std::uint8_t>* known(std::size_t capture, std::size_t cell, bool make) const;
  std::vector<std::uint32_t> blockOf_, slotOf_;  // per cell
  std::vector<std::uint32_t> blockCells_;        // per block
  std::unique_ptr<std::atomic<Block*>[]> blocks_;
};

}  // namespace probeproxy
