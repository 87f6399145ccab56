#include "core/mixing/reflected_camera.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace probeproxy {

namespace {

glm::dvec3 unitNormal(const ReflectionPlane& plane) {
  const double length = glm::length(plane.normal);
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("reflection plane normal must be finite and non-zero");
  return plane.normal / length;
}

}  // namespace

double heightAbovePlaneMeters(glm::dvec3 pointMeters, const ReflectionPlane& plane) {
  return glm::dot(pointMeters - plane.pointMeters, unitNormal(plane));
}

glm::dvec3 reflectThroughPlane(glm::dvec3 pointMeters, const ReflectionPlane& plane) {
  return pointMeters - 2.0 * heightAbovePlaneMeters(pointMeters, plane) * unitNormal(plane);
}

ReflectedCameraCheck reflectedCameraInsideProxy(glm::dvec3 cameraMeters,
                                                const ReflectionPlane& plane,
                                                const ConvexProxy& proxy) {
  ReflectedCameraCheck check;
  check.reflectedCameraMeters = reflectThroughPlane(cameraMeters, plane);
  check.outsideByMeters = signedDistanceOutside(proxy.planes, check.reflectedCameraMeters);
  check.inside = check.outsideByMeters <= 0.0;
  return check;
}

}  // namespace probeproxy
