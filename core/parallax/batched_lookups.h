#pragma once
// The seed lookups (seed_lookups.h) for many rays per call, written for speed: structure-of-
// arrays float inputs, per-proxy constants computed once (prepared_proxy.h builds them), and
// branch-free inner loops the compiler vectorizes. Same semantics, same miss rules.
//
// Every constant is stored relative to the capture point C (the positions' x - C is taken
// first, exactly, in the loop), so coordinates far from the world origin keep their precision.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

// A view over n rays (not owned): shading points in world metres and reflection directions
// (any length, not normalized), one array per coordinate, all of the same length.
struct RaysSoA {
  std::span<const float> xMeters, yMeters, zMeters;
  std::span<const float> dirX, dirY, dirZ;
  std::size_t size() const { return xMeters.size(); }
};

// Where n lookups go (not owned): d = P - C in world metres (0 on a miss) and the miss mask
// (1 = miss, the seeds' red pixel; 0 = hit).
struct LookupsSoA {
  std::span<float> dirX, dirY, dirZ;
  std::span<std::uint8_t> miss;
  std::size_t size() const { return miss.size(); }
};

struct CheapKConstants {
  glm::vec3 captureMeters{0.0f};
  float kPerMeter = 0.0f;
};

struct SphereConstants {
  glm::vec3 captureMeters{0.0f};
  glm::mat3 lightingFromWorld{1.0f};  // world metres -> lighting units (sphere radius 1)
  glm::vec3 captureInLighting{0.0f};  // C in lighting space: p = lightingFromWorld (x - C) + this
  float insideToleranceLighting = 0.0f;  // kInsideToleranceMeters / largest radius
};

struct AabbConstants {
  glm::vec3 captureMeters{0.0f};
  glm::vec3 boxMinFromCapture{0.0f};  // BoxMin - C, metres
  glm::vec3 boxMaxFromCapture{0.0f};  // BoxMax - C, metres
};

struct ObbConstants {
  glm::vec3 captureMeters{0.0f};
  glm::mat3 unitFromWorld{1.0f};        // rotation^T with row i divided by halfExtents[i]
  glm::vec3 centerFromCapture{0.0f};    // box centre - C, metres
  glm::vec3 insideToleranceUnit{0.0f};  // kInsideToleranceMeters / halfExtents
};

struct ConvexConstants {
  glm::vec3 captureMeters{0.0f};
  std::vector<glm::vec4> planesFromCapture;  // xyz outward unit normal, w = offset - dot(n, C)
};

// Each writes out[i] for every ray i. The caller checks that every span has the same length
// (lookupBatch in prepared_proxy.h does) and that no output overlaps an input (the loops are
// compiled on that promise).
void infiniteBatch(const RaysSoA& rays, const LookupsSoA& out);
void cheapKBatch(const CheapKConstants& k, const RaysSoA& rays, const LookupsSoA& out);
void sphereBatch(const SphereConstants& s, const RaysSoA& rays, const LookupsSoA& out);
void aabbBatch(const AabbConstants& box, const RaysSoA& rays, const LookupsSoA& out);
void obbBatch(const ObbConstants& box, const RaysSoA& rays, const LookupsSoA& out);
void convexBatch(const ConvexConstants& convex, const RaysSoA& rays, const LookupsSoA& out);

}  // namespace probeproxy
