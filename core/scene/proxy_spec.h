#pragma once
// What the scene file says a probe's proxy should be: generated (`auto`), none (`infinite`),
// or one an artist (or `layout`) authored. World frame (Z up), metres.

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <variant>

namespace probeproxy {

struct AutoProxy {};      // build one from the level
struct InfiniteProxy {};  // plain cubemap lookup, no parallax correction

struct AuthoredBox {  // axis-aligned in the world frame
  glm::dvec3 centerMeters{0.0};
  glm::dvec3 halfExtentsMeters{1.0};
};

struct AuthoredObb {
  glm::dvec3 centerMeters{0.0};
  glm::dvec3 halfExtentsMeters{1.0};  // in the box's own frame
  glm::dquat worldFromBox{1, 0, 0, 0};
};

struct AuthoredSphere {
  glm::dvec3 centerMeters{0.0};
  double radiusMeters = 1.0;
};

// Lagarde & Zanuttini's approximation, no shape: lookup = normalize(k * (x - C) + r).
struct AuthoredCheapK {
  double kPerMeter = 0.0;
};

struct AuthoredConvexMesh {
  std::filesystem::path mesh;           // absolute, resolved against the scene file's folder
  std::filesystem::path meshAsWritten;  // as the scene file spells it, for writing back
};

using ProxySpec = std::variant<AutoProxy, InfiniteProxy, AuthoredBox, AuthoredObb, AuthoredSphere,
                               AuthoredCheapK, AuthoredConvexMesh>;

}  // namespace probeproxy
