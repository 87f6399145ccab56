#pragma once
// How far a shrinking set of planes reaches from a point (farthestExitMeters, convex_proxy.h),
// kept up to date as planes go: the hull simplification asks it at every step whether the set
// without one more plane still stays near the room, and a fresh farthestExitMeters each time
// cost a quarter of a layout's run. The answer is the same number, bit for bit: each
// direction's exit is the least of the same per-plane distances, only found again where the
// plane that went was the one it left through.

#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace probeproxy {

class PlaneReach {
 public:
  PlaneReach(const std::vector<ProxyPlane>& planes, glm::dvec3 fromMeters,
             int directions = kReachDirections);

  // farthestExitMeters of the planes still kept, less plane j (an index into the input).
  double farthestWithoutMeters(std::size_t j) const;
  void remove(std::size_t j);

 private:
  double exitWithout(std::size_t direction, std::size_t j) const;
  void findNearest(std::size_t direction);  // nearest_ and through_ over the kept planes

  std::size_t planeCount_ = 0, directionCount_ = 0;
  std::vector<double>
      exit_;  // [direction][plane]: where the direction leaves the plane; inf if never
  std::vector<char> kept_;
  std::vector<double> nearest_;         // [direction]: the least exit over the kept planes
  std::vector<std::uint32_t> through_;  // [direction]: the kept plane it is reached at first
};

}  // namespace probeproxy
