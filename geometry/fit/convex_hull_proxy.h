#pragma once
// The convex hull of what a probe sees, as a proxy: one plane per wall, not one per triangle.

#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

#include <span>

namespace probeproxy {

// The convex hull of `pointsMeters` (CGAL's convex_hull_3, exact predicates) with its
// coplanar and nearly coplanar facets merged into planes: adjacent hull facets join a wall
// when all their corners lie within `coplanarToleranceMeters` of the wall's largest facet's
// plane and they face less than 90 degrees away from it. Each wall's plane has the
// area-weighted normal of its facets and the offset of the farthest hull corner along it, so
// the proxy contains every input point (up to rounding).
// Planes are sorted by normal (x, then y, then z) and offset; corners and triangles are
// recomputed from the planes (polytopeFromPlanes, around the mean of the hull's corners), so
// every triangle lies on its plane. A plane that ends up bounding no facet is left out.
// The same point set gives the same proxy bit for bit, in any order and on any thread.
//
// Degenerate input is an error, never a thin proxy: FitError when there are fewer than 4
// points, a coordinate is not finite, the tolerance is negative, or the points are all one
// point, on one line, on one plane (exactly), or within the tolerance of one plane (then
// the merged walls would bound no volume).
ConvexProxy convexHullProxy(std::span<const glm::dvec3> pointsMeters,
                            double coplanarToleranceMeters);

}  // namespace probeproxy
