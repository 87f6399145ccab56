#include "geometry/layout/floor_in_sight.h"

#include "geometry/raycast/room_in_sight.h"

#include <tbb/parallel_for.h>

namespace probeproxy {

namespace {

constexpr std::uint8_t kInSight = 1, kHidden = 2;

}  // namespace

FloorInSight::FloorInSight(const LevelRayCaster& level, const WalkableFloor& floor,
                           std::span<const glm::dvec3> captures)
    : level_(&level),
      cellCount_(floor.cells.size()),
      targets_(floor.cells.size()),
      viewpoints_(captures.size()),
      known_(new std::atomic<std::uint8_t>[captures.size() * floor.cells.size()]()) {
  tbb::parallel_for(std::size_t{0}, cellCount_, [&](std::size_t c) {
    targets_[c] = roomTargetsOver(level, floor.cells[c].pointMeters);
  });
  tbb::parallel_for(std::size_t{0}, captures.size(),
                    [&](std::size_t i) { viewpoints_[i] = roomViewpoints(level, captures[i]); });
}

bool FloorInSight::inSight(std::size_t capture, std::size_t cell) const {
  std::atomic<std::uint8_t>& known = known_[capture * cellCount_ + cell];
  std::uint8_t answer = known.load(std::memory_order_relaxed);
  if (answer == 0) {
    answer = roomInSight(*level_, viewpoints_[capture], targets_[cell]) ? kInSight : kHidden;
    known.store(answer, std::memory_order_relaxed);
  }
  return answer == kInSight;
}

}  // namespace probeproxy
