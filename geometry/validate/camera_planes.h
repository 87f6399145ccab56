#pragma once
// The heights at which weight_jump measures the blend, and the layout's fades with it. A camera
// can be anywhere in the head room over the walked floor (camera_space.h); the probes' capture
// heights sample that room where probes are. On hilly ground every probe's height is its own
// (a generated 80 m town: 105 heights within 3 m; silvercity 132), so a floor cell's head room
// met as many planes as there are probes near its height, and the work grew with the floor
// times the probes. One plane stands for each band of kCameraPlaneBandMeters of height, the
// lowest capture height in it: the blend varies over a fade of a metre or more, so planes
// closer than this see the same pops.

#include <span>
#include <vector>

namespace probeproxy {

constexpr double kCameraPlaneBandMeters = 0.1;

// Sorted, each at least kCameraPlaneBandMeters above the one before: from the lowest capture
// height up, each height starts a band unless it lies within the band of the one before.
std::vector<double> cameraPlaneHeights(std::span<const double> captureHeightsMeters);

}  // namespace probeproxy
