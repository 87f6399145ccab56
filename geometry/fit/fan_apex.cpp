#include "geometry/fit/fan_apex.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace probeproxy {

double smallestHeight(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const double longest = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
  return glm::length(glm::cross(b - a, c - a)) / longest;
}

std::size_t fanApex(std::span<const glm::dvec3> corners) {
  const std::size_t n = corners.size();
  std::size_t best = 0;
  double bestHeight = -1.0;
  for (std::size_t apex = 0; apex < n && n > 3; ++apex) {
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j + 1 < n; ++j) {
      lowest = std::min(lowest, smallestHeight(corners[apex], corners[(apex + j) % n],
                                               corners[(apex + j + 1) % n]));
    }
    if (lowest > bestHeight) bestHeight = lowest, best = apex;
  }
  return best;
}

}  // namespace probeproxy
