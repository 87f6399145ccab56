#pragma once
// The mixing step's reflected camera (Lagarde & Zanuttini 2012): the camera mirrored through the
// reflection plane. Its view ray through a texel is the mirror's reflected view ray, so one cubemap
// seen from it, corrected against the proxy, serves the whole planar receiver. World frame, metres.

#include "core/proxy/convex_proxy.h"
#include "core/scene/probe.h"

#include <glm/vec3.hpp>

namespace probeproxy {

// `pointMeters` mirrored through `plane` (its normal need not be unit length; a zero or
// non-finite normal throws std::invalid_argument).
glm::dvec3 reflectThroughPlane(glm::dvec3 pointMeters, const ReflectionPlane& plane);

// Signed height of a point above the plane along its normal, metres.
double heightAbovePlaneMeters(glm::dvec3 pointMeters, const ReflectionPlane& plane);

struct ReflectedCameraCheck {
  glm::dvec3 reflectedCameraMeters{0.0};
  // max over the proxy's planes of dot(n, E') - d: <= 0 when the reflected camera is inside.
  double outsideByMeters = 0.0;
  bool inside = false;  // outsideByMeters <= 0
};

// The seed's rule for glossy receivers: perturbed normals reflect rays into the lower half
// space, and from a reflected camera outside the proxy those rays miss it (red texels), so
// "artists must ensure that the reflected camera will always remain within the box volume",
// by enlarging the proxy below the floor. Says whether it does, and by how much it misses.
ReflectedCameraCheck reflectedCameraInsideProxy(glm::dvec3 cameraMeters,
                                                const ReflectionPlane& plane,
                                                const ConvexProxy& proxy);

}  // namespace probeproxy
