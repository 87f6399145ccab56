#include "core/blend/weight_continuity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace probeproxy {

namespace {

// Dense weights of one grid row: weights[col * probes + probe]; covered[col].
struct Row {
  std::vector<double> weights;
  std::vector<char> covered;
};

}  // namespace

WeightContinuity measureWeightContinuity(std::span<const InfluenceVolume> volumes,
                                         const WeightGrid& grid, const BlendOptions& options) {
  if (!(grid.spacingMeters > 0.0)) throw std::invalid_argument("weight grid: spacing must be > 0");
  if (!(grid.maxMeters.x >= grid.minMeters.x && grid.maxMeters.y >= grid.minMeters.y)) {
    throw std::invalid_argument("weight grid: empty box");
  }
  // Points at min + i * spacing, computed from the index so the grid does not drift.
  const long long cols = static_cast<long long>(std::floor((grid.maxMeters.x - grid.minMeters.x) /
                                                           grid.spacingMeters)) +
                         1;
  const long long rows = static_cast<long long>(std::floor((grid.maxMeters.y - grid.minMeters.y) /
                                                           grid.spacingMeters)) +
                         1;
  const std::size_t probes = volumes.size();

  WeightContinuity result;
  auto pointAt = [&](long long col, long long row) {
    return glm::dvec3(grid.minMeters.x + static_cast<double>(col) * grid.spacingMeters,
                      grid.minMeters.y + static_cast<double>(row) * grid.spacingMeters,
                      grid.zMeters);
  };
  auto compare = [&](const Row& a, long long colA, const Row& b, long long colB, long long rowA,
                     long long rowB) {
    if (!a.covered[colA] || !b.covered[colB]) return;
    for (std::size_t i = 0; i < probes; ++i) {
      const double jump = std::abs(a.weights[colA * probes + i] - b.weights[colB * probes + i]);
      if (jump > result.largestJump) {
        result.largestJump = jump;
        result.jumpProbe = static_cast<int>(i);
        result.jumpFromMeters = pointAt(colA, rowA);
        result.jumpToMeters = pointAt(colB, rowB);
      }
    }
  };

  Row previous, current;
  for (Row* r : {&previous, &current}) {
    r->weights.assign(static_cast<std::size_t>(cols) * probes, 0.0);
    r->covered.assign(static_cast<std::size_t>(cols), 0);
  }
  for (long long row = 0; row < rows; ++row) {
    std::fill(current.weights.begin(), current.weights.end(), 0.0);
    for (long long col = 0; col < cols; ++col) {
      const std::vector<ProbeWeight> weights = blendWeights(volumes, pointAt(col, row), options);
      current.covered[col] = !weights.empty();
      ++result.points;
      if (weights.empty()) continue;
      ++result.coveredPoints;
      double sum = 0.0;
      for (const ProbeWeight& w : weights) {
        current.weights[col * probes + static_cast<std::size_t>(w.probe)] = w.weight;
        sum += w.weight;
      }
      result.largestSumError = std::max(result.largestSumError, std::abs(sum - 1.0));
      if (col > 0) compare(current, col - 1, current, col, row, row);
      if (row > 0) compare(previous, col, current, col, row - 1, row);
    }
    std::swap(previous, current);
  }
  return result;
}

WeightGrid gridOverVolumes(std::span<const InfluenceVolume> volumes, double zMeters,
                           double spacingMeters) {
  WeightGrid grid;
  grid.zMeters = zMeters;
  grid.spacingMeters = spacingMeters;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const InfluenceVolume& v : volumes) {
    glm::dvec3 vLo, vHi;
    influenceBounds(v, vLo, vHi);
    lo = glm::min(lo, vLo);
    hi = glm::max(hi, vHi);
  }
  // Whole multiples of the spacing, so boundaries at round coordinates fall on grid points.
  grid.minMeters = glm::floor(glm::dvec2(lo) / spacingMeters) * spacingMeters;
  grid.maxMeters = glm::ceil(glm::dvec2(hi) / spacingMeters) * spacingMeters;
  return grid;
}

}  // namespace probeproxy
