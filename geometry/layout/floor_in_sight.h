#pragma once
// Which floor cells each candidate capture point holds in sight (geometry/raycast/
// room_in_sight.h, validate's influence_leak test): a probe's inner range holds only such
// floor, so no volume lights a room its probe has never seen. A candidate serves floor by its
// reflections (capture_sight.h), and a reflection off floor behind a wall can land on a
// ceiling both sides see: served, yet the leak rule's. Asked lazily (the selection asks only
// about the cells its rectangles grow over, a small part of the level for each of a thousand
// capture points) and cached in blocks of cells made on first use, so the cache grows with the
// floor each capture point is asked about, not with capture points times the level; the answer
// does not depend on who asks first, so the selection stays the same whatever the thread count.

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

  bool inSight(std::size_t capture, std::size_t cell) const;

 private:
  const LevelRayCaster* level_;
  std::size_t cellCount_;
  std::vector<RoomTargets> targets_;                 // per cell: roomTargetsOver its point
  std::vector<std::vector<glm::dvec3>> viewpoints_;  // per capture: roomViewpoints
  // [capture * blocks + cell / kBlockCells][cell % kBlockCells]: 0 not asked yet, else kInSight
  // or kHidden; a block is made by the first thread that asks about one of its cells.
  static constexpr std::size_t kBlockCells = 1024;
  using Block = std::atomic<std::uint8_t>;  // the first of kBlockCells
  std::size_t blocksPerCapture_;
  std::unique_ptr<std::atomic<Block*>[]> blocks_;
};

}  // namespace probeproxy
