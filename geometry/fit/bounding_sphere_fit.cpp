// One of the three translation units that include CGAL (with exact_hull.cpp and
// oriented_box_fit.cpp).

#include "geometry/fit/bounding_sphere_fit.h"

#include "geometry/fit/exact_hull.h"
#include "geometry/fit/fit_error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Min_sphere_of_spheres_d_traits_3.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

namespace probeproxy {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Square roots in double: the radius comes out as a plain number, not as a + b sqrt(t).
using Traits = CGAL::Min_sphere_of_spheres_d_traits_3<Kernel, double, CGAL::Tag_true>;

}  // namespace

SphereShape minimumEnclosingSphere(std::span<const glm::dvec3> points) {
  if (points.empty()) throw FitError("minimum enclosing sphere: no points to fit");
  fit::requireFinite(points, "minimum enclosing sphere");
  std::vector<Traits::Sphere> spheres;
  spheres.reserve(points.size());
  for (const glm::dvec3& p : points) spheres.emplace_back(Kernel::Point_3(p.x, p.y, p.z), 0.0);
  CGAL::Min_sphere_of_spheres_d<Traits> smallest(spheres.begin(), spheres.end());

  SphereShape sphere;
  auto coordinate = smallest.center_cartesian_begin();
  for (int i = 0; i < 3; ++i, ++coordinate) sphere.centerMeters[i] = *coordinate;
  // The farthest point sets the radius: CGAL's is as large up to rounding, and a proxy must
  // contain what the probe sees.
  double radius = 0.0;
  for (const glm::dvec3& p : points)
    radius = std::max(radius, glm::distance(p, sphere.centerMeters));
  sphere.radiiMeters = glm::dvec3(radius);
  return sphere;
}

}  // namespace probeproxy
