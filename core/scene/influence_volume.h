#pragma once
// Where a probe contributes (Lagarde & Zanuttini 2012, bonus slides): 100% inside the inner range,
// fading to 0% at the outer boundary. World frame (Z up), metres.

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <variant>

namespace probeproxy {

struct BoxInfluence {
  glm::dvec3 centerMeters{0.0};
  glm::dvec3 halfExtentsMeters{1.0};       // outer range, in the box's own frame
  glm::dquat worldFromBox{1, 0, 0, 0};     // unit quaternion, box frame -> world
  glm::dvec3 innerHalfExtentsMeters{1.0};  // inner range, <= halfExtentsMeters per axis
};

struct SphereInfluence {
  glm::dvec3 centerMeters{0.0};
  double radiusMeters = 1.0;       // outer range
  double innerRadiusMeters = 1.0;  // inner range, <= radiusMeters
};

using InfluenceVolume = std::variant<BoxInfluence, SphereInfluence>;

}  // namespace probeproxy

namespace probeproxy {

// Whether a point lies in the outer range of an influence volume.
bool insideInfluence(const InfluenceVolume& influence, glm::dvec3 pointMeters);

// Whether a point lies strictly inside the inner range: two ranges that only touch share no
// volume.
bool insideInnerRange(const InfluenceVolume& influence, glm::dvec3 pointMeters);

// The axis-aligned bounds of the outer range, world frame.
void influenceBounds(const InfluenceVolume& influence, glm::dvec3& minMeters,
                     glm::dvec3& maxMeters);
// The axis-aligned bounds of several volumes' outer ranges together; inverted (+inf, -inf)
// when there is none.
void influenceBounds(std::span<const InfluenceVolume> volumes, glm::dvec3& minMeters,
                     glm::dvec3& maxMeters);

// The outer range's volume, cubic metres (blending: the smaller volume dominates a tie).
double influenceCubicMeters(const InfluenceVolume& influence);

}  // namespace probeproxy
