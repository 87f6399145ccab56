#pragma once
// A convex proxy: the intersection of half-spaces, with its boundary as a triangle mesh.
// World frame (Z up), metres. Plain data, owns its arrays.

#include <glm/vec3.hpp>

#include <vector>

namespace probeproxy {

struct ProxyPlane {
  glm::dvec3 normal{0, 0, 1};  // unit, pointing out of the proxy
  double offsetMeters = 0.0;   // inside: dot(normal, x) <= offsetMeters
};

struct ConvexProxy {
  std::vector<ProxyPlane> planes;
  // The boundary: corners and triangles wound counter-clockwise seen from outside (so the
  // right-handed normal points out). Every triangle lies on one of `planes`.
  std::vector<glm::dvec3> verticesMeters;
  std::vector<glm::uvec3> triangles;
};

// How far x lies outside the proxy: max over planes of dot(n, x) - d (negative inside).
double signedDistanceOutside(const std::vector<ProxyPlane>& planes, glm::dvec3 xMeters);

// The boundary area on each plane (m^2), from the triangles: each triangle counts for the
// plane it lies closest to. Planes without triangles get 0.
std::vector<double> planeAreasSquareMeters(const ConvexProxy& proxy);

// How far the proxy reaches from a point inside it: the largest exit distance over a fixed
// set of `directions` spread evenly over the sphere (infinite if some direction never leaves).
// A set of planes can be bounded in theory yet reach kilometres out along a direction no
// sample tested; this is the check that keeps such proxies out.
inline constexpr int kReachDirections = 2048;
double farthestExitMeters(const std::vector<ProxyPlane>& planes, glm::dvec3 fromMeters,
                          int directions = kReachDirections);

// How far the proxy's farthest corner lies from a point (0 without corners): exact where
// farthestExitMeters samples.
double farthestCornerMeters(const ConvexProxy& proxy, glm::dvec3 fromMeters);

// Direction i of farthestExitMeters' n (a Fibonacci sphere: even coverage, no randomness).
glm::dvec3 reachDirection(int i, int directions);

// How far from `fromMeters` along unit `direction` the ray leaves the plane's half-space
// (infinite if it never does).
double planeExitMeters(const ProxyPlane& plane, glm::dvec3 fromMeters, glm::dvec3 direction);

}  // namespace probeproxy
