#pragma once
// The exact-predicate building blocks the fits share, behind a plain interface: CGAL stays in
// exact_hull.cpp (it is slow to compile), and the algorithms on top of it (facet merging, the
// polytope of half-spaces, box polishing) stay plain C++. Internal to geometry/fit.

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace probeproxy::fit {

// Throws FitError naming `what` and the first point with a NaN or infinite coordinate: CGAL's
// predicates are undefined on them.
void requireFinite(std::span<const glm::dvec3> points, std::string_view what);

// How many dimensions a point set spans, decided with exact predicates (no tolerance): -1 for
// no points, 0 for copies of one point, 1 for a line, 2 for a plane, 3 for a volume.
struct AffineSpan {
  int dimension = -1;
  std::array<std::size_t, 4> witnesses{};  // first dimension + 1 affinely independent points
};
AffineSpan affineSpan(std::span<const glm::dvec3> points);

// Exact sign of dot(cross(b - a, c - a), d - a): +1 when d lies on the side that the normal of
// the counter-clockwise triangle (a, b, c) points to, -1 on the other side, 0 when coplanar.
int orientationSign(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d);

// A closed convex triangle mesh.
struct TriangleHull {
  std::vector<glm::dvec3> vertices;  // hull corners, copies of input points (with -0 as +0)
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  // neighbors[t][e]: the triangle across edge e of triangle t, the edge from triangles[t][e]
  // to triangles[t][(e + 1) % 3].
  std::vector<std::array<std::uint32_t, 3>> neighbors;
  std::vector<std::size_t> sourceIndex;  // input index of each vertex, if asked for
};

// CGAL's convex_hull_3 (quickhull, exact predicates). Points must be finite and span a volume
// (affineSpan(points).dimension == 3), else FitError. Points inside or on the boundary but not
// at a corner are left out. `withSourceIndex` costs a hash map over the input: ask for it on
// small inputs only.
// The result depends on the point set only, not on its order nor on the heap (CGAL's own
// triangles of a flat region, and the order it makes them in, follow heap addresses): corners
// are sorted by (x, y, z); a flat region (hull triangles in one plane, exactly) becomes a fan
// from its lowest corner over its polygon's corners, counter-clockwise; triangles start at
// their lowest corner and are sorted by corners.
TriangleHull convexHull3(std::span<const glm::dvec3> points, bool withSourceIndex = false);

// The hull's triangles, counter-clockwise seen from outside, from CGAL's Triangulation_3 (exact
// predicates): for questions that every triangulation of the hull answers alike (is a point
// strictly inside it?). Robust where convex_hull_3 is not: on plane normals (every wall's normal
// on one great circle, one floor tilted by 1e-10) CGAL 5.5's quickhull fails its own assertion
// (convex_hull_3.h:684, the visible set's border is no cycle) and, built without assertions,
// crashes or returns garbage. A fraction of convexHull3's cost: no canonical form, no
// neighbours. The order follows the input's sorted order, so it is the same every run. Same
// preconditions as convexHull3.
std::vector<std::array<glm::dvec3, 3>> hullTriangles(std::span<const glm::dvec3> points);

}  // namespace probeproxy::fit
