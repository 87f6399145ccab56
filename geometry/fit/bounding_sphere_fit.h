#pragma once
// The smallest sphere around what a probe sees: the `sphere` method's `min_sphere` candidate.

#include "core/proxy/proxy_shape.h"

#include <glm/vec3.hpp>

#include <span>

namespace probeproxy {

// The minimum enclosing sphere (CGAL's Min_sphere_of_spheres_d on radius-0 spheres), with
// radiiMeters = (r, r, r) and the identity rotation. The radius is the farthest point's
// distance from the centre, so every point is inside despite rounding. One point gives radius
// 0. FitError when there are no points or a coordinate is not finite.
SphereShape minimumEnclosingSphere(std::span<const glm::dvec3> pointsMeters);

}  // namespace probeproxy
