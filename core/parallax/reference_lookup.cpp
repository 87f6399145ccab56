#include "core/parallax/reference_lookup.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <limits>

namespace probeproxy {

namespace {

std::optional<double> exitConvex(const ConvexProxy& proxy, glm::dvec3 x, glm::dvec3 r) {
  if (signedDistanceOutside(proxy.planes, x) > kInsideToleranceMeters) return std::nullopt;
  double t = std::numeric_limits<double>::infinity();
  for (const ProxyPlane& p : proxy.planes) {
    const double towards = glm::dot(p.normal, r);
    // Only planes the ray moves towards can be where it leaves; max(0, ...) keeps points that
    // sit a hair outside a plane (within the tolerance) on that plane.
    if (towards > 0)
      t = std::min(t, std::max(0.0, p.offsetMeters - glm::dot(p.normal, x)) / towards);
  }
  if (!std::isfinite(t)) return std::nullopt;
  return t;
}

std::optional<double> exitBox(const BoxShape& box, glm::dvec3 x, glm::dvec3 r) {
  const glm::dquat boxFromWorld = glm::conjugate(box.worldFromBox);
  const glm::dvec3 p = boxFromWorld * (x - box.centerMeters);
  const glm::dvec3 d = boxFromWorld * r;
  double t = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double h = box.halfExtentsMeters[axis];
    if (std::abs(p[axis]) > h + kInsideToleranceMeters) return std::nullopt;
    if (d[axis] > 0) t = std::min(t, std::max(0.0, h - p[axis]) / d[axis]);
    if (d[axis] < 0) t = std::min(t, std::min(0.0, -h - p[axis]) / d[axis]);
  }
  if (!std::isfinite(t)) return std::nullopt;
  return t;
}

std::optional<double> exitSphere(const SphereShape& sphere, glm::dvec3 x, glm::dvec3 r) {
  // In the sphere's lighting space (Bjorke, GPU Gems ch. 19) the ellipsoid is the unit sphere.
  const glm::dquat sphereFromWorld = glm::conjugate(sphere.worldFromSphere);
  const glm::dvec3 p = (sphereFromWorld * (x - sphere.centerMeters)) / sphere.radiiMeters;
  const glm::dvec3 d = (sphereFromWorld * r) / sphere.radiiMeters;
  const double scale =
      std::max(sphere.radiiMeters.x, std::max(sphere.radiiMeters.y, sphere.radiiMeters.z));
  if (glm::length(p) > 1.0 + kInsideToleranceMeters / scale) return std::nullopt;
  const double a = glm::dot(d, d);
  if (a == 0.0) return std::nullopt;
  const double b = glm::dot(p, d);
  const double c = glm::dot(p, p) - 1.0;
  const double disc = std::max(0.0, b * b - a * c);
  // The far root, written to avoid cancellation.
  const double t = c < 0 ? (b <= 0 ? (-b + std::sqrt(disc)) / a : -c / (b + std::sqrt(disc)))
                         : std::max(0.0, (-b + std::sqrt(disc)) / a);
  return t;
}

}  // namespace

std::optional<double> exitDistance(const ProxyShape& shape, glm::dvec3 x, glm::dvec3 r) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) return exitBox(*box, x, r);
  if (const auto* sphere = std::get_if<SphereShape>(&shape)) return exitSphere(*sphere, x, r);
  if (const auto* convex = std::get_if<ConvexProxy>(&shape)) return exitConvex(*convex, x, r);
  return std::nullopt;
}

std::optional<glm::dvec3> referenceLookup(const ProxyShape& shape, glm::dvec3 capture, glm::dvec3 x,
                                          glm::dvec3 r) {
  if (r == glm::dvec3(0.0)) return std::nullopt;
  if (std::holds_alternative<InfiniteShape>(shape)) return r;
  if (const auto* cheap = std::get_if<CheapKShape>(&shape)) {
    const glm::dvec3 d = cheap->kPerMeter * (x - capture) + r;
    if (d == glm::dvec3(0.0)) return std::nullopt;
    return d;
  }
  const std::optional<double> t = exitDistance(shape, x, r);
  if (!t) return std::nullopt;
  const glm::dvec3 d = x + *t * r - capture;
  if (d == glm::dvec3(0.0)) return std::nullopt;
  return d;
}

}  // namespace probeproxy
