#include "core/blend/weight_continuity.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

namespace probeproxy {

namespace {

// One grid row: dense weights[col * probes + probe], non-zero only for the row's active
// volumes (those whose bounds hold the row's line); whether each point is covered and
// reachable; whether it is reachable but uncovered (a gap to bridge).
struct Row {
  std::vector<glm::dvec3> points;
  std::vector<double> weights;
  std::vector<char> covered, reachable;
  std::vector<std::size_t> active;  // ascending
};

// Ascending indices in a or b.
std::vector<std::size_t> unionOf(const std::vector<std::size_t>& a,
                                 const std::vector<std::size_t>& b) {
  std::vector<std::size_t> both;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  return both;
}

}  // namespace

WeightContinuity measureWeightContinuity(std::span<const InfluenceVolume> volumes,
                                         const WeightGrid& grid, const BlendOptions& options,
                                         const ReachableMask& reachableMask) {
  if (!(grid.spacingMeters > 0.0)) throw std::invalid_argument("weight grid: spacing must be > 0");
  if (!(grid.maxMeters.x >= grid.minMeters.x && grid.maxMeters.y >= grid.minMeters.y)) {
    throw std::invalid_argument("weight grid: empty box");
  }
  // Points at min + i * spacing, computed from the index so the grid does not drift.
  const auto count = [&](double lo, double hi) {
    return static_cast<std::size_t>(std::floor((hi - lo) / grid.spacingMeters)) + 1;
  };
  const std::size_t cols = count(grid.minMeters.x, grid.maxMeters.x);
  const std::size_t rows = count(grid.minMeters.y, grid.maxMeters.y);
  const std::size_t probes = volumes.size();

  WeightContinuity result;
  // A volume whose bounds miss a row's line weighs 0 all along it: a map's volumes are
  // hundreds, a line crosses a few dozen. Each point is blended over the row's active volumes
  // alone (a volume outside a point takes no part in its blend), and two points are compared
  // over the volumes active in either row, in ascending order as over all of them.
  std::vector<glm::dvec3> lo(probes), hi(probes);
  for (std::size_t k = 0; k < probes; ++k) influenceBounds(volumes[k], lo[k], hi[k]);
  // Compares point i of row a with point j of row b (over `ks`) when both are covered.
  const auto compare = [&](const Row& a, std::size_t i, const Row& b, std::size_t j,
                           const std::vector<std::size_t>& ks) {
    if (!a.covered[i] || !b.covered[j]) return;
    for (std::size_t k : ks) {
      const double jump = std::abs(a.weights[i * probes + k] - b.weights[j * probes + k]);
      if (jump > result.largestJump) {
        result.largestJump = jump;
        result.jumpProbe = static_cast<int>(k);
        result.jumpFromMeters = a.points[i];
        result.jumpToMeters = b.points[j];
      }
    }
  };
  const auto isGap = [](const Row& r, std::size_t i) { return r.reachable[i] && !r.covered[i]; };

  // Rows y - 2, y - 1, y: two back, to bridge a one-point gap along y.
  std::vector<Row> ring(3);
  for (Row& r : ring) {
    r.points.resize(cols);
    r.weights.assign(cols * probes, 0.0);
    r.covered.assign(cols, 0);
    r.reachable.assign(cols, 1);
  }
  for (std::size_t row = 0; row < rows; ++row) {
    Row& current = ring[row % 3];
    const Row& previous = ring[(row + 2) % 3];
    const Row& twoBack = ring[(row + 1) % 3];
    const double y = grid.minMeters.y + static_cast<double>(row) * grid.spacingMeters;
    for (std::size_t col = 0; col < cols; ++col) {
      current.points[col] = {grid.minMeters.x + static_cast<double>(col) * grid.spacingMeters, y,
                             grid.zMeters};
    }
    if (reachableMask) reachableMask(current.points, current.reachable);
    for (std::size_t k : current.active)
      for (std::size_t col = 0; col < cols; ++col) current.weights[col * probes + k] = 0.0;
    current.active.clear();
    std::vector<InfluenceVolume> activeVolumes;
    for (std::size_t k = 0; k < probes; ++k) {
      if (lo[k].y <= y && y <= hi[k].y && lo[k].z <= grid.zMeters && grid.zMeters <= hi[k].z) {
        current.active.push_back(k);
        activeVolumes.push_back(volumes[k]);
      }
    }
    for (std::size_t col = 0; col < cols; ++col) {
      ++result.points;
      current.covered[col] = 0;
      if (!current.reachable[col]) continue;
      const std::vector<ProbeWeight> weights =
          blendWeights(activeVolumes, current.points[col], options);
      if (weights.empty()) continue;
      current.covered[col] = 1;
      ++result.coveredPoints;
      double sum = 0.0;
      for (const ProbeWeight& w : weights) {
        current.weights[col * probes + current.active[static_cast<std::size_t>(w.probe)]] =
            w.weight;
        sum += w.weight;
      }
      result.largestSumError = std::max(result.largestSumError, std::abs(sum - 1.0));
    }
    const std::vector<std::size_t> withPrevious = unionOf(previous.active, current.active);
    const std::vector<std::size_t> withTwoBack = unionOf(twoBack.active, current.active);
    for (std::size_t col = 0; col < cols; ++col) {
      if (col > 0) compare(current, col - 1, current, col, current.active);
      if (col > 1 && isGap(current, col - 1))
        compare(current, col - 2, current, col, current.active);
      if (row > 0) compare(previous, col, current, col, withPrevious);
      if (row > 1 && isGap(previous, col)) compare(twoBack, col, current, col, withTwoBack);
    }
  }
  return result;
}

WeightGrid gridOverVolumes(std::span<const InfluenceVolume> volumes, double zMeters,
                           double spacingMeters) {
  WeightGrid grid;
  grid.zMeters = zMeters;
  grid.spacingMeters = spacingMeters;
  glm::dvec3 lo, hi;
  influenceBounds(volumes, lo, hi);
  // Cell centres of a grid of whole multiples of the spacing: no point lies exactly on a wall
  // or a volume's side at a round coordinate, where nobody stands and no weight is defined.
  grid.minMeters = (glm::floor(glm::dvec2(lo) / spacingMeters) + 0.5) * spacingMeters;
  grid.maxMeters = glm::ceil(glm::dvec2(hi) / spacingMeters) * spacingMeters;
  return grid;
}

}  // namespace probeproxy
