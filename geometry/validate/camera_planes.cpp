#include "geometry/validate/camera_planes.h"

#include <algorithm>

namespace probeproxy {

std::vector<double> cameraPlaneHeights(std::span<const double> captureHeightsMeters) {
  std::vector<double> sorted(captureHeightsMeters.begin(), captureHeightsMeters.end());
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> planes;
  for (double z : sorted)
    if (planes.empty() || z >= planes.back() + kCameraPlaneBandMeters) planes.push_back(z);
  return planes;
}

}  // namespace probeproxy
