#include "geometry/layout/floor_in_sight.h"

#include "geometry/raycast/room_in_sight.h"

#include <tbb/parallel_for.h>

#include <map>
#include <utility>

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
      blockOf_(floor.cells.size()),
      slotOf_(floor.cells.size()) {
  std::map<std::pair<int, int>, std::uint32_t> blockAt;  // (row, column) of a block: its index
  for (std::size_t c = 0; c < cellCount_; ++c) {
    const FloorCell& cell = floor.cells[c];
    const auto at = std::pair(cell.row / kBlockColumns, cell.column / kBlockColumns);
    const auto [it, made] = blockAt.emplace(at, static_cast<std::uint32_t>(blockCells_.size()));
    if (made) blockCells_.push_back(0);
    blockOf_[c] = it->second;
    slotOf_[c] = blockCells_[it->second]++;
  }
  blocks_.reset(new std::atomic<Block*>[captures.size() * blockCells_.size()]());
  tbb::parallel_for(std::size_t{0}, cellCount_, [&](std::size_t c) {
    targets_[c] = roomTargetsOver(level, floor.cells[c].pointMeters);
  });
  tbb::parallel_for(std::size_t{0}, captures.size(),
                    [&](std::size_t i) { viewpoints_[i] = roomViewpoints(level, captures[i]); });
}

FloorInSight::~FloorInSight() {
  for (std::size_t b = 0; b < viewpoints_.size() * blockCells_.size(); ++b)
    delete[] blocks_[b].load();
}

std::atomic<std::uint8_t>* FloorInSight::known(std::size_t capture, std::size_t cell,
                                               bool make) const {
  const std::uint32_t b = blockOf_[cell];
  std::atomic<Block*>& slot = blocks_[capture * blockCells_.size() + b];
  Block* block = slot.load(std::memory_order_acquire);
  if (block == nullptr) {
    if (!make) return nullptr;
    Block* made = new Block[blockCells_[b]]();
    if (slot.compare_exchange_strong(block, made, std::memory_order_acq_rel))
      block = made;
    else
      delete[] made;  // another thread made it first: `block` is now that one
  }
  return &block[slotOf_[cell]];
}

bool FloorInSight::inSight(std::size_t capture, std::size_t cell) const {
  std::atomic<std::uint8_t>& known = *this->known(capture, cell, true);
  std::uint8_t answer = known.load(std::memory_order_relaxed);
  if (answer == 0) {
    answer = roomInSight(*level_, viewpoints_[capture], targets_[cell]) ? kInSight : kHidden;
    known.store(answer, std::memory_order_relaxed);
  }
  return answer == kInSight;
}

bool FloorInSight::inSightOnce(std::size_t capture, std::size_t cell) const {
  const std::atomic<std::uint8_t>* known = this->known(capture, cell, false);
  const std::uint8_t answer = known ? known->load(std::memory_order_relaxed) : 0;
  if (answer != 0) return answer == kInSight;
  return roomInSight(*level_, viewpoints_[capture], targets_[cell]);
}

}  // namespace probeproxy
