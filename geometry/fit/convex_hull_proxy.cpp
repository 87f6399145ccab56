#include "geometry/fit/convex_hull_proxy.h"

#include "geometry/fit/exact_hull.h"
#include "geometry/fit/fit_error.h"
#include "geometry/fit/polytope_from_planes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>

namespace probeproxy {

namespace {

constexpr std::uint32_t kNoWall = UINT32_MAX;

std::string countedPoints(std::size_t n) {
  return n == 1 ? std::string("the 1 point") : "all " + std::to_string(n) + " points";
}

// Why the points give no hull, in words a lighting artist can act on.
void requireVolume(std::span<const glm::dvec3> points) {
  fit::requireFinite(points, "convex hull proxy");
  if (points.size() < 4) {
    throw FitError("convex hull proxy: needs at least 4 points that span a volume, got " +
                   std::to_string(points.size()));
  }
  switch (fit::affineSpan(points).dimension) {
    case 0:
      throw FitError("convex hull proxy: " + countedPoints(points.size()) + " are the same point");
    case 1:
      throw FitError("convex hull proxy: " + countedPoints(points.size()) +
                     " are collinear: the probe sees one line only");
    case 2:
      throw FitError("convex hull proxy: " + countedPoints(points.size()) +
                     " are coplanar: the probe sees one plane only");
    default:
      break;
  }
}

struct HullFacet {
  glm::dvec3 areaVector;  // cross(b - a, c - a): twice the area, along the outward normal
  glm::dvec3 normal;      // unit
  double offsetMeters;    // dot(normal, corner), averaged over the three corners
  double area;
};

std::vector<HullFacet> hullFacets(const fit::TriangleHull& hull) {
  std::vector<HullFacet> facets;
  facets.reserve(hull.triangles.size());
  for (const auto& t : hull.triangles) {
    const glm::dvec3 a = hull.vertices[t[0]], b = hull.vertices[t[1]], c = hull.vertices[t[2]];
    HullFacet f;
    f.areaVector = glm::cross(b - a, c - a);
    f.area = 0.5 * glm::length(f.areaVector);
    // Exact predicates never make a zero-area hull facet, but its area can underflow.
    f.normal = f.area > 0 ? f.areaVector / (2.0 * f.area) : glm::dvec3(0.0);
    f.offsetMeters = (glm::dot(f.normal, a) + glm::dot(f.normal, b) + glm::dot(f.normal, c)) / 3.0;
    facets.push_back(f);
  }
  return facets;
}

// The wall of every hull facet. Walls grow from the largest facets across edges, taking a
// neighbour when all its corners lie within `toleranceMeters` of the seed facet's plane. A
// distance test, not an angle test: the thin facets that noise leaves along a room's edges
// have any normal between the two walls', yet lie within the tolerance of both; a gently
// curved wall does not. Only facets facing the seed's side (less than 90 degrees away) join:
// across the rim of a slab thinner than the tolerance lies its other face, not the same wall.
std::vector<std::uint32_t> wallOfFacet(const fit::TriangleHull& hull,
                                       const std::vector<HullFacet>& facets,
                                       double toleranceMeters) {
  std::vector<std::uint32_t> bySize(facets.size());
  std::iota(bySize.begin(), bySize.end(), 0u);
  std::stable_sort(bySize.begin(), bySize.end(), [&](std::uint32_t a, std::uint32_t b) {
    return facets[a].area > facets[b].area;
  });

  std::vector<std::uint32_t> wall(facets.size(), kNoWall);
  std::vector<std::uint32_t> queue;
  std::uint32_t wallCount = 0;
  for (std::uint32_t seed : bySize) {
    if (wall[seed] != kNoWall) continue;
    const glm::dvec3 n = facets[seed].normal;
    const double d = facets[seed].offsetMeters;
    const auto onPlane = [&](std::uint32_t f) {
      if (!(glm::dot(facets[f].normal, n) > 0)) return false;
      for (std::uint32_t v : hull.triangles[f]) {
        if (std::abs(glm::dot(n, hull.vertices[v]) - d) > toleranceMeters) return false;
      }
      return true;
    };
    wall[seed] = wallCount;
    queue.assign(1, seed);
    while (!queue.empty()) {
      const std::uint32_t f = queue.back();
      queue.pop_back();
      for (std::uint32_t next : hull.neighbors[f]) {
        if (wall[next] == kNoWall && onPlane(next)) {
          wall[next] = wallCount;
          queue.push_back(next);
        }
      }
    }
    ++wallCount;
  }
  return wall;
}

}  // namespace

ConvexProxy convexHullProxy(std::span<const glm::dvec3> points, double coplanarToleranceMeters) {
  if (!(coplanarToleranceMeters >= 0) || !std::isfinite(coplanarToleranceMeters)) {
    std::ostringstream message;
    message << "convex hull proxy: the coplanar tolerance must be finite and >= 0 m, got "
            << coplanarToleranceMeters;
    throw FitError(message.str());
  }
  requireVolume(points);
  const fit::TriangleHull hull = fit::convexHull3(points);
  const std::vector<HullFacet> facets = hullFacets(hull);

  // Exactly coplanar facets must merge even at zero tolerance: allow for the rounding of
  // dot(n, x) at the size of the coordinates (a room 10 km from the origin).
  double largestCoordinate = 0.0;
  for (const glm::dvec3& v : hull.vertices) {
    largestCoordinate = std::max({largestCoordinate, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  }
  const double rounding = 64 * std::numeric_limits<double>::epsilon() * largestCoordinate;
  const std::vector<std::uint32_t> wall =
      wallOfFacet(hull, facets, coplanarToleranceMeters + rounding);

  const std::uint32_t wallCount = *std::max_element(wall.begin(), wall.end()) + 1;
  std::vector<glm::dvec3> wallAreaVector(wallCount, glm::dvec3(0.0));
  for (std::size_t f = 0; f < facets.size(); ++f) wallAreaVector[wall[f]] += facets[f].areaVector;

  std::vector<ProxyPlane> planes;
  double thinnestMeters = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& areaVector : wallAreaVector) {
    if (!(glm::length(areaVector) > 0)) continue;
    const glm::dvec3 n = glm::normalize(areaVector);
    // The farthest corner sets the offset, so the plane keeps every point inside.
    double highest = -std::numeric_limits<double>::infinity();
    double lowest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& v : hull.vertices) {
      const double h = glm::dot(n, v);
      highest = std::max(highest, h), lowest = std::min(lowest, h);
    }
    planes.push_back({n, highest});
    thinnestMeters = std::min(thinnestMeters, highest - lowest);
  }
  if (thinnestMeters <= coplanarToleranceMeters) {
    std::ostringstream message;
    message << "convex hull proxy: " << countedPoints(points.size()) << " lie within "
            << thinnestMeters << " m of one plane (tolerance " << coplanarToleranceMeters
            << " m): the probe sees one plane only";
    throw FitError(message.str());
  }

  std::sort(planes.begin(), planes.end(), [](const ProxyPlane& a, const ProxyPlane& b) {
    return std::tie(a.normal.x, a.normal.y, a.normal.z, a.offsetMeters) <
           std::tie(b.normal.x, b.normal.y, b.normal.z, b.offsetMeters);
  });

  // Walls merged from a slab or a rod only a few tolerances thick can leave a direction open.
  if (!isBounded(planes)) {
    std::ostringstream message;
    message << "convex hull proxy: " << countedPoints(points.size()) << " lie within a few times "
            << coplanarToleranceMeters
            << " m of one plane or line: merged at that tolerance, their " << planes.size()
            << " walls bound no volume";
    throw FitError(message.str());
  }
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& v : hull.vertices) centroid += v;
  centroid /= static_cast<double>(hull.vertices.size());
  try {
    return polytopeFromPlanes(std::move(planes), centroid);
  } catch (const FitError& e) {  // only in rounding-level slivers: say whose call it was
    throw FitError(std::string("convex hull proxy: ") + e.what());
  }
}

}  // namespace probeproxy
