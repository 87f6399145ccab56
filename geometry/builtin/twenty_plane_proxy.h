#pragma once
// A convex proxy with 20 planes and known geometry: the planes tangent to an ellipsoid at the
// 20 vertex directions of a dodecahedron. The mixing-step tests and benchmark need a proxy
// that is not a box, with faces at every orientation.

#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

namespace probeproxy {

// Centre and radii in metres, world frame; the result has its corners and triangles.
ConvexProxy twentyPlaneProxy(glm::dvec3 centerMeters, glm::dvec3 radiiMeters);

}  // namespace probeproxy
