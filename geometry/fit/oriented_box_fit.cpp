// One of the three translation units that include CGAL (with exact_hull.cpp and
// bounding_sphere_fit.cpp).

// oriented_bounding_box's default traits need Eigen, and CGAL only looks for it behind this
// macro. Defined here rather than on the target: this is the only file that needs it.
#define CGAL_EIGEN3_ENABLED

#include "geometry/fit/oriented_box_fit.h"

#include "geometry/fit/exact_hull.h"
#include "geometry/fit/fit_error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>
#include <CGAL/optimal_bounding_box.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace probeproxy {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// CGAL's optimizer is randomized; a fixed seed makes the same points give the same box.
constexpr unsigned kOptimizerSeed = 1;

// A box's axes as the columns of a rotation matrix: column k is box axis k in world space.
using Axes = glm::dmat3;

struct Extent {
  glm::dvec3 lowMeters{std::numeric_limits<double>::infinity()};
  glm::dvec3 highMeters{-std::numeric_limits<double>::infinity()};
  double volume() const {
    const glm::dvec3 size = highMeters - lowMeters;
    return size.x * size.y * size.z;
  }
};

Extent extentAlong(const Axes& axes, std::span<const glm::dvec3> points) {
  Extent e;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 local(glm::dot(axes[0], p), glm::dot(axes[1], p), glm::dot(axes[2], p));
    e.lowMeters = glm::min(e.lowMeters, local);
    e.highMeters = glm::max(e.highMeters, local);
  }
  return e;
}

BoxShape boxAlong(const Axes& axes, std::span<const glm::dvec3> points) {
  const Extent e = extentAlong(axes, points);
  BoxShape box;
  box.centerMeters = axes * (0.5 * (e.lowMeters + e.highMeters));
  box.halfExtentsMeters = 0.5 * (e.highMeters - e.lowMeters);
  box.worldFromBox = glm::normalize(glm::quat_cast(axes));
  if (box.worldFromBox.w < 0) box.worldFromBox = -box.worldFromBox;
  return box;
}

glm::dvec3 anyPerpendicular(glm::dvec3 n) {
  const glm::dvec3 away = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
                              ? glm::dvec3(1, 0, 0)
                          : std::abs(n.y) <= std::abs(n.z) ? glm::dvec3(0, 1, 0)
                                                           : glm::dvec3(0, 0, 1);
  return glm::normalize(glm::cross(n, away));
}

// Columns u, cross(m, u), m: a right-handed frame with its third axis along m.
Axes frameAround(glm::dvec3 u, glm::dvec3 m) { return Axes(u, glm::cross(m, u), m); }

Axes orthonormalized(Axes a) {
  a[0] = glm::normalize(a[0]);
  a[1] = glm::normalize(a[1] - glm::dot(a[1], a[0]) * a[0]);
  a[2] = glm::cross(a[0], a[1]);  // also makes the frame right-handed
  return a;
}

// In the plane normal to unit `m`: the direction of a side of the smallest-area rectangle
// around the points' projections (CGAL's rotating calipers on their 2D hull).
glm::dvec3 smallestRectangleDirection(std::span<const glm::dvec3> points, glm::dvec3 m) {
  const glm::dvec3 a = anyPerpendicular(m), b = glm::cross(m, a);
  std::vector<Kernel::Point_2> projected;
  projected.reserve(points.size());
  for (const glm::dvec3& p : points) projected.emplace_back(glm::dot(p, a), glm::dot(p, b));
  std::vector<Kernel::Point_2> outline;  // counter-clockwise, as min_rectangle_2 needs
  CGAL::convex_hull_2(projected.begin(), projected.end(), std::back_inserter(outline));
  glm::dvec2 side(1, 0);
  if (outline.size() == 2) {
    side = {outline[1].x() - outline[0].x(), outline[1].y() - outline[0].y()};
  } else if (outline.size() > 2) {
    std::vector<Kernel::Point_2> rectangle;
    CGAL::min_rectangle_2(outline.begin(), outline.end(), std::back_inserter(rectangle));
    for (std::size_t i = 0; i + 1 < rectangle.size(); ++i) {
      side = {rectangle[i + 1].x() - rectangle[i].x(), rectangle[i + 1].y() - rectangle[i].y()};
      if (glm::length(side) > 0) break;
    }
  }
  if (!(glm::length(side) > 0)) side = {1, 0};
  side = glm::normalize(side);
  return glm::normalize(side.x * a + side.y * b);
}

glm::dvec3 farthestFrom(glm::dvec3 origin, std::span<const glm::dvec3> points) {
  glm::dvec3 best = origin;
  double bestDistance = -1;
  for (const glm::dvec3& p : points) {
    const double d = glm::distance(p, origin);
    if (d > bestDistance) best = p, bestDistance = d;
  }
  return best;
}

// The shortest rotation taking unit `from` to unit `to` (not opposite).
Axes shortestRotation(glm::dvec3 from, glm::dvec3 to) {
  return glm::mat3_cast(glm::normalize(glm::dquat(1.0 + glm::dot(from, to), glm::cross(from, to))));
}

// A box on a line: its first axis along the line, rolled as little as possible from the world.
Axes lineAxes(std::span<const glm::dvec3> points, std::size_t first) {
  const glm::dvec3 u = glm::normalize(farthestFrom(points[first], points) - points[first]);
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(u[i]) > std::abs(u[k])) k = i;
  }
  glm::dvec3 axis(0.0);
  axis[k] = u[k] > 0 ? 1.0 : -1.0;
  return shortestRotation(axis, u);
}

// A box on a plane: zero thickness along its normal, the smallest rectangle within it. The
// normal comes from the farthest points, not from the first three, which may be close.
Axes planeAxes(std::span<const glm::dvec3> points, std::size_t first) {
  const glm::dvec3 p0 = points[first];
  const glm::dvec3 p1 = farthestFrom(p0, points);
  const glm::dvec3 along = glm::normalize(p1 - p0);
  glm::dvec3 p2 = p0;
  double widest = -1;
  for (const glm::dvec3& p : points) {
    const double w = glm::length(glm::cross(p - p0, along));
    if (w > widest) p2 = p, widest = w;
  }
  const glm::dvec3 m = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  return frameAround(smallestRectangleDirection(points, m), m);
}

// CGAL's optimized box, then each of its axes snapped to the closest hull facet normal with
// the smallest rectangle across it: optimal boxes usually lie flush with a hull facet, and the
// optimizer stops near the optimum, not at it. The smallest volume wins.
Axes volumeAxes(std::span<const glm::dvec3> points) {
  const fit::TriangleHull hull = fit::convexHull3(points);
  std::vector<Kernel::Point_3> corners;
  corners.reserve(hull.vertices.size());
  for (const glm::dvec3& v : hull.vertices) corners.emplace_back(v.x, v.y, v.z);
  Kernel::Aff_transformation_3 boxFromWorld;
  // The hull's corners are the extreme points already: no second hull inside CGAL.
  CGAL::oriented_bounding_box(corners, boxFromWorld,
                              CGAL::parameters::use_convex_hull(false).random_seed(kOptimizerSeed));
  Axes optimized;
  for (int k = 0; k < 3; ++k) {
    optimized[k] = {boxFromWorld.m(k, 0), boxFromWorld.m(k, 1), boxFromWorld.m(k, 2)};
  }
  Axes best = orthonormalized(optimized);
  double bestVolume = extentAlong(best, hull.vertices).volume();

  std::vector<glm::dvec3> facetNormals;
  facetNormals.reserve(hull.triangles.size());
  for (const auto& t : hull.triangles) {
    const glm::dvec3 a = hull.vertices[t[0]];
    const glm::dvec3 n = glm::cross(hull.vertices[t[1]] - a, hull.vertices[t[2]] - a);
    if (glm::length(n) > 0) facetNormals.push_back(glm::normalize(n));
  }
  const Axes start = best;
  for (int k = 0; k < 3; ++k) {
    glm::dvec3 m = facetNormals.front();
    for (const glm::dvec3& n : facetNormals) {
      if (std::abs(glm::dot(n, start[k])) > std::abs(glm::dot(m, start[k]))) m = n;
    }
    const Axes snapped = frameAround(smallestRectangleDirection(hull.vertices, m), m);
    const double volume = extentAlong(snapped, hull.vertices).volume();
    if (volume < bestVolume) best = snapped, bestVolume = volume;
  }
  return best;
}

// A box has 24 proper rotations (its axes permuted and flipped); pick the one closest to the
// identity, the largest trace, so the same box always comes out the same.
Axes canonical(Axes axes) {
  if (glm::determinant(axes) < 0) axes[2] = -axes[2];
  static constexpr int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                              {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  Axes best = axes;
  double bestTrace = -std::numeric_limits<double>::infinity();
  for (const auto& perm : kPermutations) {
    for (int signs = 0; signs < 8; ++signs) {
      Axes candidate;
      for (int j = 0; j < 3; ++j) candidate[j] = ((signs >> j) & 1 ? -1.0 : 1.0) * axes[perm[j]];
      if (glm::determinant(candidate) <= 0) continue;
      const double trace = candidate[0][0] + candidate[1][1] + candidate[2][2];
      if (trace > bestTrace) best = candidate, bestTrace = trace;
    }
  }
  return best;
}

BoxShape canonicalBoxAlong(const Axes& axes, std::span<const glm::dvec3> points) {
  BoxShape box = boxAlong(canonical(axes), points);
  // An axis-aligned room should come out as an aabb, not as an obb turned by rounding.
  const glm::dquat q = box.worldFromBox;
  if (2.0 * std::atan2(glm::length(glm::dvec3(q.x, q.y, q.z)), q.w) < 1e-9)
    box = boxAlong(Axes(1.0), points);
  return box;
}

void requirePoints(std::span<const glm::dvec3> points, std::string_view what) {
  if (points.empty()) throw FitError(std::string(what) + ": no points to fit");
  fit::requireFinite(points, what);
}

}  // namespace

BoxShape orientedBoxFit(std::span<const glm::dvec3> points) {
  requirePoints(points, "oriented box fit");
  const fit::AffineSpan span = fit::affineSpan(points);
  Axes axes(1.0);
  switch (span.dimension) {
    case 0:
      break;
    case 1:
      axes = lineAxes(points, span.witnesses[0]);
      break;
    case 2:
      axes = planeAxes(points, span.witnesses[0]);
      break;
    default:
      axes = volumeAxes(points);
      break;
  }
  return canonicalBoxAlong(axes, points);
}

BoxShape uprightBoxFit(std::span<const glm::dvec3> points) {
  requirePoints(points, "upright box fit");
  const glm::dvec3 up(0, 0, 1);
  return canonicalBoxAlong(frameAround(smallestRectangleDirection(points, up), up), points);
}

BoxShape axisAlignedBoxFit(std::span<const glm::dvec3> points) {
  requirePoints(points, "axis-aligned box fit");
  return boxAlong(Axes(1.0), points);
}

}  // namespace probeproxy
