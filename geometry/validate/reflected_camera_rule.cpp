// reflected_camera_outside_proxy, Lagarde & Zanuttini's rule for planar receivers: the mixing-step
// correction casts the reflected camera's view rays against the proxy, so "artists must ensure
// that the reflected camera will always remain within the box volume" for glossy receivers.
// For a mirror the weaker condition holds: the receiver under each camera must be inside the
// proxy, or the reflected rays through it never cross the proxy where the receiver is.

#include "geometry/validate/validation_rules.h"

#include <glm/geometric.hpp>

#include <cstdio>

namespace probeproxy {

void checkReflectedCameras(const LevelRayCaster& level, const Probe& probe,
                           const ProxyShape& authored, const ValidateOptions& options,
                           std::vector<ValidationFinding>& out) {
  if (probe.reflectionPlanes.empty() || std::holds_alternative<InfiniteShape>(authored) ||
      std::holds_alternative<CheapKShape>(authored))
    return;
  const std::vector<glm::dvec3> cameras = reflectionCameras(level, probe, options.samples);
  // A point on a plane is "inside" a convex proxy whose face lies in that plane: allow for
  // rounding.
  constexpr double kOnBoundaryMeters = 1e-6;
  double worst = 0.0;
  glm::dvec3 worstCamera(0.0);
  for (const ReflectionPlane& plane : probe.reflectionPlanes) {
    for (const glm::dvec3& eye : cameras) {
      const double height = glm::dot(plane.normal, eye - plane.pointMeters);
      if (height <= 0.0) continue;  // a camera below the receiver does not see it
      // A camera behind a wall from the capture point is influence_leak's business.
      if (level.firstHit({probe.captureMeters, glm::vec3(eye - probe.captureMeters), 0.0f, 0.999f})
              .hit())
        continue;
      const glm::dvec3 tested =
          options.glossyReceivers ? eye - 2.0 * height * plane.normal : eye - height * plane.normal;
      const double outside = metersOutside(authored, tested);
      if (outside > kOnBoundaryMeters && outside > worst) worst = outside, worstCamera = eye;
    }
  }
  if (worst == 0.0) return;
  char text[200];
  std::snprintf(text, sizeof text, "' proxy: %s camera at %s is %.3f m outside it",
                options.glossyReceivers ? "the reflected" : "the planar receiver under the",
                formatPoint(worstCamera).c_str(), worst);
  out.push_back({probe.name, "reflected_camera_outside_proxy", "warning", worst, 0.0,
                 "probe '" + probe.name + text,
                 options.glossyReceivers
                     ? "enlarge the proxy below the reflection plane until it holds the "
                       "reflected cameras (Lagarde & Zanuttini's glossy rule)"
                     : "move the proxy's face down onto the reflection plane (or below it)"});
}

}  // namespace probeproxy
