#include "geometry/validate/weld_positions.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace probeproxy {

namespace {

// A grid cell, kept as doubles: floor() of a far coordinate over a tiny tolerance can exceed
// any integer type, and merging such cells only costs time (distances are still checked).
struct Cell {
  double x, y, z;
  bool operator==(const Cell&) const = default;
};

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    const std::hash<double> h;
    std::size_t seed = h(c.x);
    seed ^= h(c.y) + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2);
    seed ^= h(c.z) + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2);
    return seed;
  }
};

}  // namespace

std::vector<std::uint32_t> weldPositions(std::span<const glm::dvec3> positions, double tolerance) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("weldPositions: tolerance must be finite and >= 0, got " +
                                std::to_string(tolerance));
  }
  std::vector<std::uint32_t> weldedTo(positions.size());
  if (positions.empty()) return weldedTo;

  glm::dvec3 lo = positions[0];
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p);
  // With no tolerance, cells of any size work: only exact matches weld.
  const double cellSize = tolerance > 0.0 ? tolerance : 1.0;
  const auto cellOf = [&](const glm::dvec3& p) {
    const glm::dvec3 c = glm::floor((p - lo) / cellSize);
    return Cell{c.x, c.y, c.z};
  };

  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> representatives;
  representatives.reserve(positions.size());
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    const glm::dvec3& p = positions[i];
    const Cell home = cellOf(p);
    std::uint32_t best = i;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = representatives.find({home.x + dx, home.y + dy, home.z + dz});
          if (it == representatives.end()) continue;
          for (std::uint32_t j : it->second) {
            if (j < best && glm::distance(p, positions[j]) <= tolerance) best = j;
          }
        }
      }
    }
    weldedTo[i] = best;
    if (best == i) representatives[home].push_back(i);
  }
  return weldedTo;
}

}  // namespace probeproxy
