#include "geometry/layout/widen_fades.h"

#include "core/blend/weight_continuity.h"
#include "geometry/layout/bands_in_sight.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/layout/volume_columns.h"
#include "geometry/validate/camera_planes.h"
#include "geometry/validate/camera_space.h"
#include "geometry/validate/influence_out_of_sight.h"

#include <tbb/blocked_range.h>
#include <tbb/concurrent_unordered_map.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace probeproxy {

namespace {

// The blend is measured on this grid, as overlap_trim.h checks its trims; validate's is 1 cm
// on a small level and 4-7 cm on a corpus map, placed otherwise, so a spot counts as smooth
// only this far under the limit.
constexpr double kScanGridMeters = 0.05;
constexpr double kShareOfLimit = 0.9;
// Points a side of a floor cell's coarse grid, where a scan looks first.
constexpr int kCoarsePoints = 4;
// Walked cells the scan of the whole floor takes at a time.
constexpr std::size_t kScanBlockCells = 4096;

// The widenings tried, in gaps (the layout's band), the least first; an inner range keeps at
// least kLeastInnerHalfOverGap of a gap either side of its centre (widerFades).
constexpr std::array<double, 3> kInnerShrinksOverGap{0.25, 0.5, 1.0};
constexpr double kLeastInnerHalfOverGap = 0.25;
constexpr std::array<double, 3> kOuterGrowthsOverGap{0.125, 0.25, 0.5};
// A spot a widening made smoother but left over the limit may take another, up to this many.
constexpr int kMostWideningsPerSpot = 3;

struct Pop {
  double perCentimeter = 0.0;
  glm::dvec3 from{0.0}, to{0.0};
  // Worst first; ties by position, so the order does not depend on the threads.
  auto order() const { return std::tuple(-perCentimeter, from.x, from.y, from.z, to.x, to.y); }
};

// What one floor cell's cameras at one height see of the blend.
struct CellBlend {
  glm::dvec3 floorMeters{0.0};
  double zMeters = 0.0;     // the cameras' height
  int mostOverlapping = 0;  // outer ranges over one camera point outside every inner range
  Pop pop;                  // its steepest turn; 0 per cm unless over the scan's threshold
};

struct BlendScan {
  std::vector<CellBlend> cells;  // in the walked floor's order, then by height
  double steepestPerCentimeter() const {
    double steepest = 0.0;
    for (const CellBlend& c : cells) steepest = std::max(steepest, c.pop.perCentimeter);
    return steepest;
  }
};

struct Region {
  glm::dvec3 lo{0.0}, hi{0.0};
};

bool meets(const Region& r, glm::dvec3 lo, glm::dvec3 hi) {
  return glm::all(glm::lessThanEqual(r.lo, hi)) && glm::all(glm::lessThanEqual(lo, r.hi));
}

// Whether one of the layout's inner ranges holds the whole square at height z: one probe takes
// the whole weight there, and nothing pops.
bool insideOneInnerRange(std::span<const InfluenceVolume> near, glm::dvec2 lo, glm::dvec2 hi,
                         double z) {
  return std::any_of(near.begin(), near.end(), [&](const InfluenceVolume& v) {
    const std::optional<InnerRange> r = innerRangeOf(v);
    return r && r->lo.x < lo.x && hi.x < r->hi.x && r->lo.y < lo.y && hi.y < r->hi.y &&
           r->lo.z < z && z < r->hi.z;
  });
}

// Where a camera can be on each walked cell's scan grid at a capture height, remembered: a
// spot is scanned again for every widening tried, and the cameras do not move. A slot holds one
// cell's rows at one height in the order the scan asks for them, made when a scan first
// measures that cell at that height (few do: most cells' weights never turn enough), so the
// cache grows with the floor near the bands, not with the floor times the heights. A scan's
// tasks each ask for a slot of their own, so they need no lock but the map's.
class CameraSpaceCache {
 public:
  // One cell's rows at one height, end to end (a row is the scan grid's points along x).
  using Slot = std::vector<char>;
  CameraSpaceCache(const LevelRayCaster& level, const WalkableFloor& walked, double headRoom,
                   std::span<const double> heights)
      : level_(level), walked_(walked), headRoom_(headRoom), heights_(heights) {}
  // The slot of a cell at one of the heights.
  Slot& slot(std::size_t cell, double z) {
    const auto height = static_cast<std::size_t>(
        std::lower_bound(heights_.begin(), heights_.end(), z) - heights_.begin());
    return slots_.emplace(cell * heights_.size() + height, Slot{}).first->second;
  }
  // Where a camera can be, measured and not kept: the whole-floor scan measures every
  // cell-height once, and kept, its slots (some 130 bytes each) number millions on a 25 ha
  // level; the scans after it, around the pops, keep theirs.
  ReachableMask unkeptMask() const {
    return [this](std::span<const glm::dvec3> points, std::span<char> reachable) {
      markCameraSpace(level_, walked_, headRoom_, points, reachable);
    };
  }
  ReachableMask mask(Slot& slot) const {
    return [this, &slot, at = std::size_t{0}](std::span<const glm::dvec3> points,
                                              std::span<char> reachable) mutable {
      if (at == slot.size()) {
        slot.resize(at + points.size(), 0);
        markCameraSpace(level_, walked_, headRoom_, points,
                        std::span<char>(slot).subspan(at, points.size()));
      }
      std::copy_n(slot.begin() + static_cast<std::ptrdiff_t>(at), points.size(), reachable.begin());
      at += points.size();
    };
  }

 private:
  const LevelRayCaster& level_;
  const WalkableFloor& walked_;
  double headRoom_;
  std::span<const double> heights_;  // sorted, each once
  tbb::concurrent_unordered_map<std::size_t, Slot> slots_;
};

// A block of the walked cells, [first, end), that the scan of the whole floor takes at a time.
struct CellSpan {
  std::size_t first = 0, end = 0;
};

// One walked cell at one camera height.
struct BlendTask {
  std::size_t cell = 0;
  double z = 0.0;
};

// Calls f(cell index) for the walked cells of the grid columns and rows the region's plan
// covers, and a cell more either side (the caller tests each exactly), in index order: a scan
// of a spot looks at a few cells, not at the whole floor's.
template <class F>
void forEachCellNear(const WalkableFloor& walked, const Region& region, F&& f) {
  if (walked.cells.empty()) return;
  const auto index = [&](double meters, double origin, int count) {
    const double at = std::floor((meters - origin) / walked.spacingMeters);
    return static_cast<int>(std::clamp(at, -1.0, static_cast<double>(count)));
  };
  const int c0 = index(region.lo.x, walked.originMeters.x, walked.columns) - 1;
  const int c1 = index(region.hi.x, walked.originMeters.x, walked.columns) + 1;
  const int r0 = std::max(0, index(region.lo.y, walked.originMeters.y, walked.rows) - 1);
  const int r1 =
      std::min(walked.rows - 1, index(region.hi.y, walked.originMeters.y, walked.rows) + 1);
  const auto before = [](const FloorCell& cell, std::pair<int, int> at) {
    return std::pair(cell.row, cell.column) < at;
  };
  for (int r = r0; r <= r1; ++r) {
    auto it = std::lower_bound(walked.cells.begin(), walked.cells.end(), std::pair(r, c0), before);
    for (; it != walked.cells.end() && it->row == r && it->column <= c1; ++it)
      f(static_cast<std::size_t>(it - walked.cells.begin()));
  }
}

// The walked cells that meet the region (all of the floor's, or those of a block `cells`),
// each at the heights within it a camera over that cell can be at.
std::vector<BlendTask> blendTasks(const WalkableFloor& walked, double headRoom,
                                  std::span<const double> heights, const Region& region,
                                  std::optional<CellSpan> cells = std::nullopt) {
  const double halfCell = 0.5 * walked.spacingMeters;
  std::vector<BlendTask> tasks;
  const auto take = [&](std::size_t c) {
    const glm::dvec3 f = walked.cells[c].pointMeters;
    if (!meets(region, f - glm::dvec3(halfCell, halfCell, 0.0),
               f + glm::dvec3(halfCell, halfCell, headRoom)))
      return;
    for (auto z = std::lower_bound(heights.begin(), heights.end(), f.z);
         z != heights.end() && *z <= f.z + headRoom; ++z)
      if (region.lo.z <= *z && *z <= region.hi.z) tasks.push_back({c, *z});
  };
  if (cells) {
    for (std::size_t c = cells->first; c < std::min(cells->end, walked.cells.size()); ++c) take(c);
  } else {
    forEachCellNear(walked, region, take);
  }
  return tasks;
}

// A task's square on the scan grid: whole multiples of kScanGridMeters (shared by neighbouring
// cells, one point past its low sides so every neighbouring pair is compared).
WeightGrid taskGrid(const WalkableFloor& walked, const BlendTask& task) {
  const double halfCell = 0.5 * walked.spacingMeters, s = kScanGridMeters;
  const glm::dvec3 f = walked.cells[task.cell].pointMeters;
  const glm::dvec2 cellLo = glm::dvec2(f) - halfCell;
  WeightGrid grid;
  grid.zMeters = task.z;
  grid.spacingMeters = s;
  grid.minMeters = (glm::ceil((cellLo - s) / s - 0.5) + 0.5) * s;
  grid.maxMeters = glm::dvec2(f) + halfCell;
  return grid;
}

// Whether a volume within these bounds takes part in the blend over the grid (the others leave
// that blend as it is).
bool reachesGrid(const Region& bounds, const WeightGrid& grid) {
  return bounds.lo.x < grid.maxMeters.x && grid.minMeters.x < bounds.hi.x &&
         bounds.lo.y < grid.maxMeters.y && grid.minMeters.y < bounds.hi.y &&
         bounds.lo.z < grid.zMeters && grid.zMeters < bounds.hi.z;
}

std::vector<Region> boundsOf(std::span<const InfluenceVolume> volumes) {
  std::vector<Region> bounds(volumes.size());
  for (std::size_t v = 0; v < volumes.size(); ++v)
    influenceBounds(volumes[v], bounds[v].lo, bounds[v].hi);
  return bounds;
}

VolumeColumns columnsOf(std::span<const Region> bounds) {
  std::vector<glm::dvec3> lo, hi;
  for (const Region& b : bounds) lo.push_back(b.lo), hi.push_back(b.hi);
  return VolumeColumns(lo, hi);
}

// The volumes that may reach a task's square, in increasing order (`widened`: one more,
// grown past the bounds the columns were made from).
void volumesNear(const VolumeColumns& columns, const WeightGrid& grid,
                 std::vector<std::uint32_t>& out,
                 std::optional<std::uint32_t> widened = std::nullopt) {
  columns.near(grid.minMeters, grid.maxMeters, out);
  if (widened && !std::binary_search(out.begin(), out.end(), *widened))
    out.insert(std::upper_bound(out.begin(), out.end(), *widened), *widened);
}

// The blend where a camera can be over one task's square, among `candidates` (the volumes that
// may reach it, in increasing order: volumesNear). Only a pop over `popThreshold` is measured
// (pop.perCentimeter stays 0 otherwise).
CellBlend scanTask(const WalkableFloor& walked, std::span<const InfluenceVolume> volumes,
                   std::span<const Region> bounds, std::span<const std::uint32_t> candidates,
                   const BlendTask& task, double popThreshold, CameraSpaceCache& cameraSpace,
                   bool keepCameras = true) {
  const WeightGrid grid = taskGrid(walked, task);
  const double z = task.z, s = kScanGridMeters;
  CellBlend found;
  found.floorMeters = walked.cells[task.cell].pointMeters;
  found.zMeters = z;
  std::vector<InfluenceVolume> near;
  for (std::uint32_t v : candidates)
    if (reachesGrid(bounds[v], grid)) near.push_back(volumes[v]);
  if (near.size() < 2 || insideOneInnerRange(near, grid.minMeters, grid.maxMeters, z)) return found;
  // First on a coarse grid over the cell: what overlaps, and whether any weight turns by
  // as much as a pop does in one step (weights turn one way across a band: a pop within the
  // cell shows between its corners).
  int most = 0;
  std::vector<double> least(near.size(), 1.0), largest(near.size(), 0.0), w(near.size());
  for (int i = 0; i < kCoarsePoints; ++i) {
    for (int j = 0; j < kCoarsePoints; ++j) {
      const glm::dvec2 span = grid.maxMeters - grid.minMeters;
      const glm::dvec3 p(grid.minMeters.x + i * span.x / (kCoarsePoints - 1),
                         grid.minMeters.y + j * span.y / (kCoarsePoints - 1), z);
      std::fill(w.begin(), w.end(), 0.0);
      for (const ProbeWeight& pw : blendWeights(near, p)) w[pw.probe] = pw.weight;
      int over = 0;
      bool inner = false;
      for (std::size_t k = 0; k < near.size(); ++k) {
        least[k] = std::min(least[k], w[k]);
        largest[k] = std::max(largest[k], w[k]);
        over += insideInfluence(near[k], p);
        inner = inner || insideInnerRange(near[k], p);
      }
      if (!inner) most = std::max(most, over);
    }
  }
  double turn = 0.0;
  for (std::size_t k = 0; k < near.size(); ++k) turn = std::max(turn, largest[k] - least[k]);
  found.mostOverlapping = most;
  if (turn < popThreshold * 100.0 * s) return found;
  const WeightContinuity c = measureWeightContinuity(
      near, grid, {},
      keepCameras ? cameraSpace.mask(cameraSpace.slot(task.cell, z)) : cameraSpace.unkeptMask());
  const double perCentimeter = c.largestJump / (100.0 * s);
  if (perCentimeter > popThreshold) found.pop = {perCentimeter, c.jumpFromMeters, c.jumpToMeters};
  return found;
}

// The blend where a camera can be over the walked cells that meet the region, at the heights
// within it; steepestPerCentimeter is the steepest pop over `popThreshold`, 0 when there is none.
// A block of the whole floor's cells (`cells`) keeps none of its cameras (unkeptMask).
BlendScan scanBlend(const WalkableFloor& walked, double headRoom,
                    std::span<const InfluenceVolume> volumes, std::span<const double> heights,
                    const Region& region, double popThreshold, CameraSpaceCache& cameraSpace,
                    std::optional<CellSpan> cells = std::nullopt) {
  const bool keepCameras = !cells;
  const std::vector<BlendTask> tasks = blendTasks(walked, headRoom, heights, region, cells);
  const std::vector<Region> bounds = boundsOf(volumes);  // once, not for every cell
  const VolumeColumns columns = columnsOf(bounds);
  BlendScan scan;
  scan.cells.resize(tasks.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tasks.size()), [&](const auto& range) {
    std::vector<std::uint32_t> candidates;
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      volumesNear(columns, taskGrid(walked, tasks[t]), candidates);
      scan.cells[t] = scanTask(walked, volumes, bounds, candidates, tasks[t], popThreshold,
                               cameraSpace, keepCameras);
    }
  });
  return scan;
}

// Whether the blend over a task's square stays as it was when `box` becomes `wider`:
// - the square lies inside both inner ranges: the volume takes the whole weight there either
//   way, and the scan passes it by (insideOneInnerRange); most of a box is its inner range;
// - or an inner range shrank (the outer range and so the size, the blend's tie-break, the
//   same), and along every axis it shrank the square lies inside both inner ranges: Lagarde's
//   factor is a product over the box's axes, that axis's factor 1 either way.
bool blendStaysOver(const BoxInfluence& box, const BoxInfluence& wider, const WeightGrid& grid) {
  const std::array<InfluenceVolume, 2> both{box, wider};
  const auto insideInner = [&](const InfluenceVolume& v) {
    return insideOneInnerRange(std::span(&v, 1), grid.minMeters, grid.maxMeters, grid.zMeters);
  };
  if (insideInner(both[0]) && insideInner(both[1])) return true;
  if (wider.halfExtentsMeters != box.halfExtentsMeters || wider.worldFromBox != box.worldFromBox ||
      box.worldFromBox != glm::dquat(1.0, 0.0, 0.0, 0.0))
    return false;
  const glm::dvec3 lo(grid.minMeters, grid.zMeters), hi(grid.maxMeters, grid.zMeters);
  for (int axis = 0; axis < 3; ++axis) {
    if (wider.innerHalfExtentsMeters[axis] == box.innerHalfExtentsMeters[axis]) continue;
    const double inside =
        std::min(wider.innerHalfExtentsMeters[axis], box.innerHalfExtentsMeters[axis]);
    const double c = box.centerMeters[axis];
    if (!(c - inside < lo[axis] && hi[axis] < c + inside)) return false;
  }
  return true;
}

Region boundsOf(const InfluenceVolume& v) {
  Region r;
  influenceBounds(v, r.lo, r.hi);
  return r;
}

// Whether a widening of one volume leaves, away from the spot, no cell's blend turning steeper
// than the limit or than it did, and no more volumes meeting over a camera than the blend takes
// or than did, at every height over the region its widest growth reaches. Most widenings fail
// near the spot, where the band that pops goes on, so cells are taken nearest the spot first
// and the check stops at the first that got worse; the blend as it is, measured once a cell,
// serves every widening of the volume tried at this spot.
class AwayFromSpot {
 public:
  struct Limits {
    double perCentimeter = 0.0;
    int overlap = 0;
  };
  AwayFromSpot(const WalkableFloor& walked, double headRoom, std::span<const double> heights,
               const Region& over, const Region& spot, Limits limits,
               std::span<const InfluenceVolume> volumes, CameraSpaceCache& cameraSpace)
      : walked_(walked),
        spot_(spot),
        limits_(limits),
        volumes_(volumes),
        bounds_(boundsOf(volumes)),
        columns_(columnsOf(bounds_)),
        cameraSpace_(cameraSpace),
        tasks_(blendTasks(walked, headRoom, heights, over)) {
    const glm::dvec2 centre = 0.5 * (glm::dvec2(spot.lo) + glm::dvec2(spot.hi));
    const auto distance = [&](const BlendTask& t) {
      const glm::dvec2 d = glm::dvec2(walked.cells[t.cell].pointMeters) - centre;
      return glm::dot(d, d);
    };
    std::sort(tasks_.begin(), tasks_.end(), [&](const BlendTask& x, const BlendTask& y) {
      return std::tuple(distance(x), x.cell, x.z) < std::tuple(distance(y), y.cell, y.z);
    });
    before_.resize(tasks_.size());
  }

  // Volume v as `wider` instead of as it is.
  bool noWorse(std::size_t v, const BoxInfluence& wider) {
    std::vector<InfluenceVolume> after(volumes_.begin(), volumes_.end());
    after[v] = wider;
    std::vector<Region> afterBounds = bounds_;
    influenceBounds(after[v], afterBounds[v].lo, afterBounds[v].hi);
    // A cell the wider volume does not reach blends as before (it holds the volume as it is),
    // and so does one where the widening leaves every weight as it was.
    const BoxInfluence& box = std::get<BoxInfluence>(volumes_[v]);
    std::vector<std::size_t> changed;
    for (std::size_t t = 0; t < tasks_.size(); ++t) {
      const WeightGrid grid = taskGrid(walked_, tasks_[t]);
      if (reachesGrid(afterBounds[v], grid) && !blendStaysOver(box, wider, grid))
        changed.push_back(t);
    }
    const double halfCell = 0.5 * walked_.spacingMeters;
    for (std::size_t first = 0; first < changed.size(); first += kCellsAtATime) {
      const std::size_t end = std::min(changed.size(), first + kCellsAtATime);
      std::vector<CellBlend> afterCells(end - first);
      tbb::parallel_for(first, end, [&](std::size_t i) {
        const std::size_t t = changed[i];
        const WeightGrid grid = taskGrid(walked_, tasks_[t]);
        std::vector<std::uint32_t> candidates;
        if (!before_[t]) {
          volumesNear(columns_, grid, candidates);
          before_[t] = scanTask(walked_, volumes_, bounds_, candidates, tasks_[t],
                                limits_.perCentimeter, cameraSpace_);
        }
        volumesNear(columns_, grid, candidates, static_cast<std::uint32_t>(v));
        afterCells[i - first] = scanTask(walked_, after, afterBounds, candidates, tasks_[t],
                                         limits_.perCentimeter, cameraSpace_);
      });
      for (std::size_t i = first; i < end; ++i) {
        const CellBlend& b = *before_[changed[i]];
        const CellBlend& a = afterCells[i - first];
        if (a.mostOverlapping > std::max(limits_.overlap, b.mostOverlapping)) return false;
        const glm::dvec3 at(a.floorMeters.x, a.floorMeters.y, a.zMeters);
        const glm::dvec3 half(halfCell, halfCell, 0.0);
        if (meets(spot_, at - half, at + half)) continue;
        if (a.pop.perCentimeter > std::max(limits_.perCentimeter, b.pop.perCentimeter))
          return false;
      }
    }
    return true;
  }

 private:
  // Enough to keep the threads busy, few enough to stop soon after the first cell that fails.
  static constexpr std::size_t kCellsAtATime = 64;
  const WalkableFloor& walked_;
  Region spot_;
  Limits limits_;
  std::span<const InfluenceVolume> volumes_;  // as they are
  std::vector<Region> bounds_;
  VolumeColumns columns_;  // of the volumes as they are
  CameraSpaceCache& cameraSpace_;
  std::vector<BlendTask> tasks_;
  std::vector<std::optional<CellBlend>> before_;
};

// The walked cells of the grid columns and rows a region's plan covers, in the floor's order:
// every cell a volume within the region weighs, and some it does not. The leak check walks
// these, not the whole floor (millions of cells on an open level, for each widening tried).
std::vector<FloorCell> cellsUnder(const WalkableFloor& walked, const Region& region) {
  std::vector<FloorCell> cells;
  forEachCellNear(walked, region, [&](std::size_t c) { cells.push_back(walked.cells[c]); });
  return cells;
}

// The cells round a pop, at its height.
Region around(const Pop& pop, double cellMeters) {
  const glm::dvec3 margin(cellMeters, cellMeters, 0.0);
  return {glm::min(pop.from, pop.to) - margin, glm::max(pop.from, pop.to) + margin};
}

// The fades tried along one axis, the least change first: the inner range shrinking (the band
// grows inwards; the outer range stays, so nothing reaches further), then the outer range
// growing (where only two bands' far ends meet, each weighs (1 - a) / a ~ d / b, d into its
// band: the share turns across the width both reach, whatever their bands' depths, and only
// reaching further widens it). Both sides of the axis: a box has one centre.
std::vector<BoxInfluence> widerFades(const BoxInfluence& box, int axis, double gapMeters) {
  std::vector<BoxInfluence> wider;
  for (double w : kInnerShrinksOverGap) {
    BoxInfluence b = box;
    b.innerHalfExtentsMeters[axis] = std::max(kLeastInnerHalfOverGap * gapMeters,
                                              box.innerHalfExtentsMeters[axis] - w * gapMeters);
    if (b.innerHalfExtentsMeters[axis] < box.innerHalfExtentsMeters[axis]) wider.push_back(b);
  }
  for (double g : kOuterGrowthsOverGap) {
    BoxInfluence b = box;
    b.halfExtentsMeters[axis] += g * gapMeters;
    wider.push_back(b);
  }
  return wider;
}

}  // namespace

std::size_t widenFadesWhereWeightsJump(const LevelRayCaster& level, const WalkableFloor& walked,
                                       double gapMeters, const ValidateOptions& limits,
                                       std::span<const InfluenceVolume> kept,
                                       std::vector<LayoutProbe>& probes) {
  std::vector<InfluenceVolume> volumes(kept.begin(), kept.end());
  std::vector<double> captureHeights;
  for (const LayoutProbe& p : probes) {
    volumes.push_back(p.influence);
    captureHeights.push_back(p.captureMeters.z);
  }
  const std::vector<double> heights = cameraPlaneHeights(captureHeights);  // validate's planes
  if (volumes.empty() || walked.cells.empty()) return 0;

  const double headRoom = limits.cameraHeadRoomMeters;
  const double target = kShareOfLimit * limits.maxWeightJumpPerCentimeter;
  CameraSpaceCache cameraSpace(level, walked, headRoom, heights);
  const auto scan = [&](const Region& region, std::span<const double> zs, double threshold,
                        std::optional<CellSpan> cells = std::nullopt) {
    return scanBlend(walked, headRoom, volumes, zs, region, threshold, cameraSpace, cells);
  };
  Region everywhere;
  influenceBounds(volumes, everywhere.lo, everywhere.hi);
  // The whole floor a block of cells at a time: a scan holds a result per cell and height.
  std::vector<Pop> pops;
  for (std::size_t first = 0; first < walked.cells.size(); first += kScanBlockCells)
    for (const CellBlend& c :
         scan(everywhere, heights, target, CellSpan{first, first + kScanBlockCells}).cells)
      if (c.pop.perCentimeter > 0.0) pops.push_back(c.pop);
  std::sort(pops.begin(), pops.end(),
            [](const Pop& a, const Pop& b) { return a.order() < b.order(); });

  // A band that pops along its length shows in every cell beside it; once no widening of the
  // volumes reaching one of its spots helped, the others, with those volumes as they were, are
  // left as they are (on bleach each was tried again, cell after cell, for minutes).
  std::vector<int> changes(volumes.size(), 0);
  std::set<std::vector<std::pair<std::size_t, int>>> triedInVain;
  std::size_t widened = 0;
  for (const Pop& pop : pops) {
    const Region spot = around(pop, walked.spacingMeters);
    const std::array<double, 1> spotHeight{pop.from.z};
    for (int round = 0; round < kMostWideningsPerSpot; ++round) {
      // A band's spots tried in vain are passed over before they are scanned again: on hilly
      // ground nearly all are.
      std::vector<std::pair<std::size_t, int>> reaching;  // the layout's volumes, as they are
      for (std::size_t v = kept.size(); v < volumes.size(); ++v)
        if (insideInfluence(volumes[v], pop.from) || insideInfluence(volumes[v], pop.to))
          reaching.emplace_back(v, changes[v]);
      if (triedInVain.count(reaching)) break;
      const double now = scan(spot, spotHeight, target).steepestPerCentimeter();
      if (now <= target) break;
      // The axis the weight turns along first.
      const glm::dvec3 step = glm::abs(pop.to - pop.from);
      const std::array<int, 2> axes = step.x >= step.y ? std::array{0, 1} : std::array{1, 0};
      std::optional<std::pair<std::size_t, BoxInfluence>> chosen, smoother;
      double smoothest = now;
      for (std::size_t v = kept.size(); v < volumes.size() && !chosen; ++v) {
        const BoxInfluence box = std::get<BoxInfluence>(volumes[v]);
        if (!insideInfluence(box, pop.from) && !insideInfluence(box, pop.to)) continue;
        // Checked over the box its widest growth reaches: outside a widening's own bounds no
        // weight changes, so one scan before serves every widening tried.
        BoxInfluence widest = box;
        for (int axis : {0, 1})
          widest.halfExtentsMeters[axis] += kOuterGrowthsOverGap.back() * gapMeters;
        std::optional<AwayFromSpot> away;
        std::optional<double> leakBefore;
        std::vector<FloorCell> underWidest;  // what the leak check weighs, box and widenings
        for (int axis : axes) {
          for (const BoxInfluence& wider : widerFades(box, axis, gapMeters)) {
            volumes[v] = wider;
            const double spotAfter = scan(spot, spotHeight, target).steepestPerCentimeter();
            volumes[v] = box;
            if (!(spotAfter < now)) continue;
            // A grown range is checked for its sight first: most fail there, and the check
            // away from the spot takes every cell of the box when it passes.
            if (wider.halfExtentsMeters != box.halfExtentsMeters) {  // reaches further
              const glm::dvec3 capture = probes[v - kept.size()].captureMeters;
              if (!leakBefore) {
                underWidest = cellsUnder(walked, boundsOf(widest));
                leakBefore = influenceOutOfSight(level, capture, box, underWidest).share;
              }
              if (influenceOutOfSight(level, capture, wider, underWidest).share >
                  std::max(*leakBefore, kLeakShareTarget))
                continue;
            }
            if (!away)
              away.emplace(walked, headRoom, heights, boundsOf(widest), spot,
                           AwayFromSpot::Limits{target, limits.maxOverlap}, volumes, cameraSpace);
            if (!away->noWorse(v, wider)) continue;
            if (spotAfter <= target) {
              chosen = {v, wider};
              break;
            }
            if (spotAfter < smoothest) smoothest = spotAfter, smoother = {v, wider};
          }
          if (chosen) break;
        }
      }
      if (!chosen) chosen = smoother;
      if (!chosen) {
        triedInVain.insert(std::move(reaching));
        break;
      }
      ++changes[chosen->first];
      volumes[chosen->first] = chosen->second;
      probes[chosen->first - kept.size()].influence = chosen->second;
      ++widened;
    }
  }
  return widened;
}

}  // namespace probeproxy
