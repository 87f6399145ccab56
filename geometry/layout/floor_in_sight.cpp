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
      blocksPerCapture_((floor.cells.size() + kBlockCells - 1) / kBlockCells),
      blocks_(new std::atomic<Block*>[captures.size() * blocksPerCapture_]()) {
  tbb::parallel_for(std::size_t{0}, cellCount_, [&](std::size_t c) {
    targets_[c] = roomTargetsOver(level, floor.cells[c].pointMeters);
  });
  tbb::parallel_for(std::size_t{0}, captures.size(),
                    [&](std::size_t i) { viewpoints_[i] = roomViewpoints(level, captures[i]); });
}

FloorInSight::~FloorInSight() {
  for (std::size_t b = 0; b < viewpoints_.size() * blocksPerCapture_; ++b)
    delete[] blocks_[b].load();
}

bool FloorInSight::inSight(std::size_t capture, std::size_t cell) const {
  std::atomic<Block*>& slot = blocks_[capture * blocksPerCapture_ + cell / kBlockCells];
  Block* block = slot.load(std::memory_order_acquire);
  if (block == nullptr) {
    Block* made = new Block[kBlockCells]();
    if (slot.compare_exchange_strong(block, made, std::memory_order_acq_rel))
      block = made;
    else
      delete[] made;  // another thread made it first: `block` is now that one
  }
  std::atomic<std::uint8_t>& known = block[cell % kBlockCells];
  std::uint8_t answer = known.load(std::memory_order_relaxed);
  if (answer == 0) {
    answer = roomInSight(*level_, viewpoints_[capture], targets_[cell]) ? kInSight : kHidden;
    known.store(answer, std::memory_order_relaxed);
  }
  return answer == kInSight;
}

}  // namespace probeproxy
