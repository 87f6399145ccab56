#pragma once
// What error-driven tuning minimizes: the mean angular error over the visible samples, with a
// miss costing kMissCostDeg. A miss shows the seeds' red pixel or a wrong colour, far worse
// than any parallax error, so no tuning step may buy accuracy with misses.

#include <cmath>

namespace probeproxy {

inline constexpr double kMissCostDeg = 180.0;  // as bad as the worst possible error

inline double sampleCostDeg(double errorDeg) {
  return std::isnan(errorDeg) ? kMissCostDeg : errorDeg;
}

}  // namespace probeproxy
