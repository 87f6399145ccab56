#include "geometry/builtin/twenty_plane_proxy.h"

#include "geometry/fit/polytope_from_planes.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace probeproxy {

ConvexProxy twentyPlaneProxy(glm::dvec3 centerMeters, glm::dvec3 radiiMeters) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> directions;
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) directions.emplace_back(x, y, z);
  for (double a : {-1.0, 1.0}) {
    for (double b : {-1.0, 1.0}) {
      directions.emplace_back(0.0, a / phi, b * phi);
      directions.emplace_back(a / phi, b * phi, 0.0);
      directions.emplace_back(a * phi, 0.0, b / phi);
    }
  }
  std::vector<ProxyPlane> planes;
  for (const glm::dvec3& d : directions) {
    const glm::dvec3 n = glm::normalize(d);
    // Support function of the ellipsoid: the tangent plane with normal n.
    planes.push_back({n, glm::dot(n, centerMeters) + glm::length(radiiMeters * n)});
  }
  return polytopeFromPlanes(planes, centerMeters);
}

}  // namespace probeproxy
