#include "geometry/tune/plane_reach.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace probeproxy {

PlaneReach::PlaneReach(const std::vector<ProxyPlane>& planes, glm::dvec3 from, int directions)
    : planeCount_(planes.size()),
      directionCount_(static_cast<std::size_t>(std::max(directions, 0))),
      exit_(directionCount_ * planeCount_),
      kept_(planeCount_, 1),
      nearest_(directionCount_),
      through_(directionCount_, 0) {
  for (std::size_t d = 0; d < directionCount_; ++d) {
    const glm::dvec3 v = reachDirection(static_cast<int>(d), directions);
    for (std::size_t p = 0; p < planeCount_; ++p)
      exit_[d * planeCount_ + p] = planeExitMeters(planes[p], from, v);
    findNearest(d);
  }
}

void PlaneReach::findNearest(std::size_t d) {
  nearest_[d] = std::numeric_limits<double>::infinity();
  through_[d] = static_cast<std::uint32_t>(planeCount_);  // none: the direction never leaves
  for (std::size_t p = 0; p < planeCount_; ++p) {
    if (kept_[p] && exit_[d * planeCount_ + p] < nearest_[d])
      nearest_[d] = exit_[d * planeCount_ + p], through_[d] = static_cast<std::uint32_t>(p);
  }
}

double PlaneReach::exitWithout(std::size_t d, std::size_t j) const {
  double exit = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < planeCount_; ++p)
    if (kept_[p] && p != j) exit = std::min(exit, exit_[d * planeCount_ + p]);
  return exit;
}

double PlaneReach::farthestWithoutMeters(std::size_t j) const {
  double farthest = 0.0;
  for (std::size_t d = 0; d < directionCount_; ++d)
    farthest = std::max(farthest, through_[d] == j ? exitWithout(d, j) : nearest_[d]);
  return farthest;
}

void PlaneReach::remove(std::size_t j) {
  kept_[j] = 0;
  for (std::size_t d = 0; d < directionCount_; ++d)
    if (through_[d] == j) findNearest(d);
}

}  // namespace probeproxy
