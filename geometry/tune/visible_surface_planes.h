#pragma once
// Candidate half-spaces from the surfaces a probe sees. A convex hull only has planes on its
// outside; in a concave room (an L, a U, a hall with pillars) the walls that fold inwards are
// the planes a good proxy needs. Every large planar surface the depth cube hits becomes a
// half-space that keeps the capture point inside, and error-driven selection decides which of
// them earn their place.

#include "core/proxy/convex_proxy.h"
#include "geometry/raycast/ray.h"

#include <span>
#include <vector>

namespace probeproxy {

// `hits` are a depth cube's (castDepthCubeRays). Surfaces are grouped by plane (normals within
// `angleToleranceDeg`, offsets within `offsetToleranceMeters`); a group must cover at least
// `minShare` of the cube's texels. At most `maxPlanes` planes, the most seen first; a plane
// through the capture point is skipped (it cannot keep the capture point strictly inside).
std::vector<ProxyPlane> visibleSurfacePlanes(std::span<const RayHit> hits, glm::dvec3 captureMeters,
                                             int faceSize, double offsetToleranceMeters,
                                             double angleToleranceDeg = 1.0,
                                             double minShare = 0.002, std::size_t maxPlanes = 48);

}  // namespace probeproxy
