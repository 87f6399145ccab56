#include "geometry/fit/fan_apex.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace probeproxy {

std::size_t fanApex(std::span<const glm::dvec3> corners) {
  const std::size_t n = corners.size();
  std::size_t best = 0;
  double bestHeight = -1.0;
  for (std::size_t apex = 0; apex < n && n > 3; ++apex) {
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j + 1 < n; ++j) {
      const glm::dvec3 a = corners[apex], b = corners[(apex + j) % n],
                       c = corners[(apex + j + 1) % n];
      const double longest =
          std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
      lowest = std::min(lowest, glm::length(glm::cross(b - a, c - a)) / longest);
    }
    if (lowest > bestHeight) bestHeight = lowest, best = apex;
  }
  return best;
}

}  // namespace probeproxy
