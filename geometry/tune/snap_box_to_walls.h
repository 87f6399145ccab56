#pragma once
// A box fitted to the corners of a probe's hull sits a hull tolerance (millimetres) outside the
// walls it touches, which shows as a few hundredths of a degree of error. Where a box face is
// parallel to a wall the probe sees and that close to it, the face moves onto the wall, so a
// box room's fitted box is the room itself.

#include "core/proxy/convex_proxy.h"
#include "core/proxy/proxy_shape.h"

#include <span>

namespace probeproxy {

// Each of the box's six faces whose outward normal is within `angleToleranceDeg` of a wall's
// and whose offset is within `offsetToleranceMeters` of it takes the wall's offset; the other
// faces stay. The rotation never changes. `walls` are outward half-spaces (visibleSurfacePlanes).
BoxShape snapBoxToWalls(const BoxShape& box, std::span<const ProxyPlane> walls,
                        double offsetToleranceMeters, double angleToleranceDeg = 0.05);

}  // namespace probeproxy
