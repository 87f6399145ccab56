#pragma once
// The mixing step by rasterization (Lagarde & Zanuttini 2012, "Rasterizing parallax corrected
// cubemap"): the convex proxy, each vertex carrying its direction from the capture point (vertex -
// C), is drawn from the reflected camera E' into the six 90-degree faces with front faces culled,
// so only the faces whose outward normal points away from E' are drawn: the far side, where each
// ray through the proxy leaves it. The interpolated direction is the lookup vector; a texel no
// triangle covers is a miss. It handles any convex proxy, not only boxes, and gives the same lookup
// cube as mixing_plane.h (the tests hold the two within half a texel).

#include "core/mixing/lookup_cube.h"
#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

namespace probeproxy {

// Throws std::invalid_argument for a face size below 1, a proxy without triangles, or a
// non-finite point.
LookupCube rasterConvexLookups(const ConvexProxy& proxy, glm::dvec3 captureMeters,
                               glm::dvec3 reflectedCameraMeters, int faceSize);

}  // namespace probeproxy
