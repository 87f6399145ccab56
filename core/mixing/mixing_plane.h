#pragma once
// The mixing-step correction per texel (Lagarde & Zanuttini 2012, "Mixing Step"): the camera is
// mirrored through the reflection plane (reflected_camera.h) and, for every texel direction d of a
// cube centred at that reflected camera E', the ray (E', d) is intersected with the convex proxy.
// The point P where it LEAVES the proxy is what the mirror shows (E' usually lies below the
// floor, outside the proxy, so the ray first enters it), and the probe's cubemap is looked up
// at P - C. The seed's OBB shader code is this with six planes.

#include "core/mixing/lookup_cube.h"
#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

#include <vector>

namespace probeproxy {

// The parameter interval a line origin + t * direction spends inside the half-spaces:
// enter = max over planes it crosses inwards, exit = min over planes it crosses outwards
// (+-infinity where there are none). A line parallel to a plane and strictly outside it gets
// enter = +inf, exit = -inf. The chord is empty when exit <= enter.
struct RayChord {
  double enter = 0.0;
  double exit = 0.0;
};
RayChord rayChord(const std::vector<ProxyPlane>& planes, glm::dvec3 originMeters,
                  glm::dvec3 direction);

// Whether the ray leaves the proxy ahead of its origin through a non-empty chord:
// exit > max(enter, minExit). A ray from a point on the boundary that leaves at once (exit
// within minExit, in units of |direction|, of the origin) is a miss, as the rasterizer's near
// plane makes it.
bool rayExitsProxy(const RayChord& chord, double minExit = 0.0);

// The per-texel lookup cube of the mixing step. Throws std::invalid_argument for a face size
// below 1, a proxy without planes, or a non-finite point.
LookupCube mixingPlaneLookups(const ConvexProxy& proxy, glm::dvec3 captureMeters,
                              glm::dvec3 reflectedCameraMeters, int faceSize);

}  // namespace probeproxy
