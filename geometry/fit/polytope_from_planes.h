#pragma once
// The convex polytope that a set of half-spaces bounds, as corners and triangles: what engines
// draw and Blender shows for a proxy that the fit only knows as planes.

#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace probeproxy {

// The intersection of the half-spaces dot(n, x) <= d (CGAL's dual convex hull, the method of
// halfspace_intersection_3). `interiorPointMeters` must lie strictly inside every half-space:
// the probe's capture point. Planes that do not bound the result with a facet of their own
// (parallel planes farther out, duplicates, planes that only touch a corner or an edge) are
// left out: the result's `planes` are the kept ones, in their input order, and
// `droppedPlaneIndices`, if given, receives the indices of the others, ascending.
// Triangles come plane by plane in that order, counter-clockwise seen from outside; corners
// are sorted by (x, y, z). Corners closer than 1e-5 of the polytope's size are one corner,
// solved from the best conditioned three of the planes that meet there: the result depends on
// the planes and the interior point only, bit for bit (not on the thread, nor on the heap).
// Throws FitError when a normal is not unit length or a value is not finite, when the planes
// bound no volume (isBounded is false), when the interior point is not strictly inside, or when
// rounding leaves no closed boundary even without the planes whose facets have no area: the
// mesh it returns is always closed.
ConvexProxy polytopeFromPlanes(std::vector<ProxyPlane> planes, glm::dvec3 interiorPointMeters,
                               std::vector<std::size_t>* droppedPlaneIndices = nullptr);

// Whether the half-spaces leave no direction open, so that their intersection, where it is
// not empty, is bounded: no unit v has dot(n_i, v) < 1e-3 for every plane (the origin at
// least 1e-3 inside the convex hull of the normals). A set that fails by less than that is
// bounded in exact arithmetic but reaches over 1000 times its offsets out along v, so it is
// taken as open. Offsets play no part. Fewer than 4 planes, or normals that are not finite,
// are never bounded.
bool isBounded(const std::vector<ProxyPlane>& planes);

}  // namespace probeproxy
