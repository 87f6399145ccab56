#pragma once
// What shaders intersect reflection rays in: a box's "unit box space" (Lagarde & Zanuttini 2012:
// the OBB is turned into [-1, 1]^3 by WorldToLocal before the slab test) and a sphere's "lighting
// space" (Bjorke, GPU Gems ch. 19: the unit sphere under a 4x4 transform, so ellipsoids too).
// Frame-free: the same formula gives a world matrix from a world shape and a file matrix from a
// file shape.

#include "core/proxy/convex_proxy.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace probeproxy {

// unit = diag(1 / halfExtents) * conjugate(rotation) * (x - center): the box's corners go to
// (+-1, +-1, +-1), an ellipsoid with these radii to the unit sphere.
glm::dmat4 toUnitTransform(glm::dvec3 center, glm::dvec3 halfExtents, const glm::dquat& rotation);

// An icosphere (the icosahedron subdivided `subdivisions` times, 162 vertices at 2) on the
// ellipsoid, wound counter-clockwise from outside. For display only: its faces are not what
// the sphere method intersects, so no planes come with it.
ConvexProxy icosphereMesh(glm::dvec3 center, glm::dvec3 radii, const glm::dquat& rotation,
                          int subdivisions = 2);

}  // namespace probeproxy
