#include "geometry/fit/fan_apex.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace probeproxy {

namespace {

// Folds shallower than this times the facet's size are rounding of a planar facet.
constexpr double kFoldToleranceRelative = 1e-9;
// So are folds the written mesh cannot hold: its corners are floats, rounded by half an epsilon
// of their largest coordinate. Ranked by folds of a few micrometres, a 66 m facet of
// dieselpower's layout was fanned from the one corner in line with two others (a triangle
// 2.6e-7 m high, validate's proxy_degenerate_face; in the file's floats its plane pointed
// anywhere, and validate found the capture point 1.85 m outside the proxy).
constexpr double kFoldToleranceFloatEpsilons = 8.0;

// How far the fan from `apex` folds inwards at worst: the largest distance of a fan triangle's
// next corner outside that triangle's plane (0 or less for a fan that only folds outwards).
double deepestInwardFold(std::span<const glm::dvec3> corners, std::size_t apex) {
  const std::size_t n = corners.size();
  const glm::dvec3 a = corners[apex];
  double deepest = -std::numeric_limits<double>::infinity();
  for (std::size_t j = 1; j + 2 < n; ++j) {
    const glm::dvec3 b = corners[(apex + j) % n], c = corners[(apex + j + 1) % n];
    const glm::dvec3 normal = glm::cross(b - a, c - a);  // outwards: counter-clockwise
    const double length = glm::length(normal);
    if (length == 0.0) continue;
    deepest = std::max(deepest, glm::dot(normal / length, corners[(apex + j + 2) % n] - a));
  }
  return deepest;
}

}  // namespace

double smallestHeight(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const double longest = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
  return glm::length(glm::cross(b - a, c - a)) / longest;
}

std::size_t fanApex(std::span<const glm::dvec3> corners) {
  const std::size_t n = corners.size();
  double size = 0.0, farthestCoordinate = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    size = std::max(size, glm::distance(corners[0], corners[i]));
    const glm::dvec3 c = glm::abs(corners[i]);
    farthestCoordinate = std::max({farthestCoordinate, c.x, c.y, c.z});
  }
  const double foldTolerance = std::max(
      kFoldToleranceRelative * size,
      kFoldToleranceFloatEpsilons * std::numeric_limits<float>::epsilon() * farthestCoordinate);
  std::size_t best = 0;
  double bestHeight = -1.0, bestFold = std::numeric_limits<double>::infinity();
  for (std::size_t apex = 0; apex < n && n > 3; ++apex) {
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j + 1 < n; ++j) {
      lowest = std::min(lowest, smallestHeight(corners[apex], corners[(apex + j) % n],
                                               corners[(apex + j + 1) % n]));
    }
    const double fold = std::max(deepestInwardFold(corners, apex), foldTolerance);
    if (fold < bestFold || (fold == bestFold && lowest > bestHeight))
      bestFold = fold, bestHeight = lowest, best = apex;
  }
  return best;
}

}  // namespace probeproxy
