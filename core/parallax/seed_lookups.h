#pragma once
// Scalar float ports of the seeds' parallax-correction shader code, one ray per call, written
// line by line after the shaders so they can be read side by side with the seeds. World frame
// (Z up), metres. Same semantics as referenceLookup (reference_lookup.h):
//   lookup d = P - C, P = x + t r where the ray (x, r) leaves the proxy, C the capture point;
//   a miss is flagged (and d set to 0) for x outside the proxy (beyond kInsideToleranceMeters),
//   a ray that never leaves (unbounded planes), a zero r, or P landing on C.
// Division by zero gives +-inf as in the shaders and the comparisons filter it out; nothing
// here returns NaN or inf. Never build with -ffast-math.
//
// d is not normalized: the cubemap fetch does not need it (Lagarde & Zanuttini's cheap_k normalize
// is left to the caller, as the other methods' texCUBE(envMap, ReflDirectionWS) leave it).

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>

namespace probeproxy::seed {

struct Lookup {
  glm::vec3 direction{0.0f};  // d = P - C, world frame, metres (0 on a miss)
  bool miss = true;           // the seeds' red pixel
};

// No correction: d = r.
Lookup infinite(glm::vec3 r);

// Lagarde & Zanuttini 2012 (NVIDIA / ATI demos): D = normalize(K * (Pp - C) + R), returned
// unnormalized.
Lookup cheapK(float kPerMeter, glm::vec3 captureMeters, glm::vec3 xMeters, glm::vec3 r);

// Bjorke, GPU Gems ch. 19: the unit sphere centred at the origin of lighting space;
// lightingFromWorld maps world metres into it (an ellipsoid in the world when it scales
// unevenly). The lighting-space capture point need not be the sphere's centre.
Lookup sphere(const glm::mat4& lightingFromWorld, float insideToleranceLighting,
              glm::vec3 captureMeters, glm::vec3 xMeters, glm::vec3 r);

// Lagarde & Zanuttini 2012 AABB code (and Czuba's): the box [boxMinMeters, boxMaxMeters] in world
// axes.
Lookup aabb(glm::vec3 boxMinMeters, glm::vec3 boxMaxMeters, glm::vec3 captureMeters,
            glm::vec3 xMeters, glm::vec3 r);

// Lagarde & Zanuttini 2012 OBB code: into the unit box's space ([-1, 1]^3) and back. unitFromWorld
// is the box's rotation transposed with each row divided by its half-extent; boxCenterMeters is
// subtracted first (the seed's affine WorldToLocal, split so large coordinates keep their
// precision). insideToleranceUnit is kInsideToleranceMeters / halfExtents, per axis.
Lookup obb(const glm::mat3& unitFromWorld, glm::vec3 boxCenterMeters, glm::vec3 insideToleranceUnit,
           glm::vec3 captureMeters, glm::vec3 xMeters, glm::vec3 r);

// Lagarde & Zanuttini's convex volumes: k planes (xyz unit outward normal, w offset in metres:
// inside is dot(n, x) <= w); the exit is the nearest plane the ray moves towards (slab test).
Lookup convex(std::span<const glm::vec4> planes, glm::vec3 captureMeters, glm::vec3 xMeters,
              glm::vec3 r);

}  // namespace probeproxy::seed
