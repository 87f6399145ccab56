#pragma once
// Rays against the level. World frame (Z up), metres.

#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>

namespace probeproxy {

struct Ray {
  // Double, so a level far from the world origin keeps its precision: the ray caster works
  // relative to the level's own centre.
  glm::dvec3 originMeters{0.0};
  glm::vec3 direction{0, 0, 1};  // need not be unit; distances below are in units of its length
  float tMin = 0.0f;
  float tMax = std::numeric_limits<float>::infinity();
};

inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;

struct RayHit {
  float t = std::numeric_limits<float>::infinity();  // hit = origin + t * direction; inf: none
  std::uint32_t triangle = kNoTriangle;              // index into LevelMesh::triangles
  glm::vec3 geometricNormal{0.0f};                   // unit, world, as wound (not flipped)

  bool hit() const { return triangle != kNoTriangle; }
};

struct SurfacePoint {
  double distanceMeters = std::numeric_limits<double>::infinity();
  std::uint32_t triangle = kNoTriangle;  // index into LevelMesh::triangles; none: kNoTriangle
};

}  // namespace probeproxy
