#include "core/parallax/seed_lookups.h"

#include "core/parallax/reference_lookup.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy::seed {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kTolerance = static_cast<float>(kInsideToleranceMeters);

// d = (x - C) + r t, the seeds' `IntersectPositionWS - CubemapPositionWS` with the subtraction
// done first: far from the origin x and C are close, so x - C is exact and P - C is not.
Lookup finish(glm::vec3 xMinusCapture, glm::vec3 r, float t) {
  Lookup out;
  if (!(t < kInf)) return out;  // also false for NaN
  const glm::vec3 d = xMinusCapture + r * t;
  if (d == glm::vec3(0.0f)) return out;
  if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) return out;
  out.direction = d;
  out.miss = false;
  return out;
}

// HLSL's max/min on finite-or-inf values (no NaN reaches them).
float hmax(float a, float b) { return a > b ? a : b; }
float hmin(float a, float b) { return a < b ? a : b; }

}  // namespace

Lookup infinite(glm::vec3 r) {
  Lookup out;
  if (r == glm::vec3(0.0f)) return out;
  out.direction = r;
  out.miss = false;
  return out;
}

Lookup cheapK(float kPerMeter, glm::vec3 capture, glm::vec3 x, glm::vec3 r) {
  // Lagarde & Zanuttini 2012, slide "Cheaper approximation exists":
  //   D = normalize(K * (Pp - C) + R)
  Lookup out;
  if (r == glm::vec3(0.0f)) return out;
  const glm::vec3 d = kPerMeter * (x - capture) + r;
  if (d == glm::vec3(0.0f)) return out;  // normalize(0) is the NaN the shader would return
  if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) return out;
  out.direction = d;
  out.miss = false;
  return out;
}

Lookup sphere(const glm::mat4& lightingFromWorld, float insideToleranceLighting, glm::vec3 capture,
              glm::vec3 x, glm::vec3 r) {
  // Bjorke, GPU Gems ch. 19 (Listings 19-1 and 19-2):
  //   float4 Pu = mul(LightingXf, Pw);                     // the point in lighting space
  //   float b = -2.0 * dot(reflVect, IN.LightingPos);
  //   float c = dot(IN.LightingPos, IN.LightingPos) - 1.0;
  //   float discrim = b * b - 4.0 * c;
  //   if (discrim > 0) hasIntersects = ((abs(sqrt(discrim) - b) / 2.0) > 0.00001);
  //   reflVect = nearT * reflVect - IN.LightingPos;
  // The listing normalizes reflVect in lighting space and leaves nearT undefined; here the ray
  // keeps its length (a = dot(d, d)) so t is the same in lighting space and in the world, the
  // far root is taken in the half-b form without cancellation, and the red pixel (a point
  // outside the sphere) is the miss flag instead of the 1e-5 epsilon.
  Lookup out;
  const glm::vec3 p = glm::vec3(lightingFromWorld * glm::vec4(x, 1.0f));
  const glm::vec3 d = glm::mat3(lightingFromWorld) * r;
  const float a = glm::dot(d, d);
  if (!(a > 0.0f)) return out;
  const float b = glm::dot(p, d);  // half of the quadratic's b, sign flipped from the seed
  const float c = glm::dot(p, p) - 1.0f;
  const float outer = 1.0f + insideToleranceLighting;
  if (glm::dot(p, p) > outer * outer) return out;  // shaded outside the sphere: red
  const float discrim = std::max(0.0f, b * b - a * c);
  const float root = std::sqrt(discrim);
  float t;
  if (c < 0.0f)
    t = b <= 0.0f ? (root - b) / a : -c / (b + root);
  else
    t = std::max(0.0f, (root - b) / a);  // on the sphere, within the tolerance
  return finish(x - capture, r, t);
}

Lookup aabb(glm::vec3 boxMin, glm::vec3 boxMax, glm::vec3 capture, glm::vec3 x, glm::vec3 r) {
  // Lagarde & Zanuttini 2012, "parallax-correction code for an AABB geometry proxy":
  //   float3 FirstPlaneIntersect = (BoxMax - PositionWS) / ReflDirectionWS;
  //   float3 SecondPlaneIntersect = (BoxMin - PositionWS) / ReflDirectionWS;
  //   float3 FurthestPlane = max(FirstPlaneIntersect, SecondPlaneIntersect);
  //   float Distance = min(min(FurthestPlane.x, FurthestPlane.y), FurthestPlane.z);
  //   float3 IntersectPositionWS = PositionWS + ReflDirectionWS * Distance;
  //   ReflDirectionWS = IntersectPositionWS - CubemapPositionWS;
  Lookup out;
  if (r == glm::vec3(0.0f)) return out;
  const glm::vec3 tol(kTolerance);
  if (glm::any(glm::lessThan(x, boxMin - tol)) || glm::any(glm::greaterThan(x, boxMax + tol)))
    return out;  // the shader assumes x inside; outside is the red pixel
  const glm::vec3 first = (boxMax - x) / r;
  const glm::vec3 second = (boxMin - x) / r;
  glm::vec3 furthest;
  for (int i = 0; i < 3; ++i) {
    // "Ok because x/0 give +inf and -x/0 give -inf": but 0/0 (x on a face, r parallel to it)
    // is NaN, so an axis the ray does not move along is dropped explicitly.
    furthest[i] = r[i] != 0.0f ? hmax(first[i], second[i]) : kInf;
  }
  const float distance = hmin(hmin(furthest.x, furthest.y), furthest.z);
  // A point within the tolerance outside a face, moving out of it, leaves at once.
  return finish(x - capture, r, hmax(0.0f, distance));
}

Lookup obb(const glm::mat3& unitFromWorld, glm::vec3 boxCenter, glm::vec3 toleranceUnit,
           glm::vec3 capture, glm::vec3 x, glm::vec3 r) {
  // Lagarde & Zanuttini 2012, "Intersection with OBB convert to unit box space":
  //   float3 RayLS = mul((float3x3)WorldToLocal, RayWS);
  //   float3 ReflCameraLS = mul(WorldToLocal, ReflCameraWS);
  //   float3 Unitary = float3(1.0f, 1.0f, 1.0f);
  //   float3 FirstPlaneIntersect = (Unitary - ReflCameraLS) / RayLS;
  //   float3 SecondPlaneIntersect = (-Unitary - ReflCameraLS) / RayLS;
  //   float3 FurthestPlane = max(FirstPlaneIntersect, SecondPlaneIntersect);
  //   float Distance = min(FurthestPlane.x, min(FurthestPlane.y, FurthestPlane.z));
  //   float3 IntersectPositionWS = ReflCameraWS + RayWS * Distance;
  //   float3 ReflDirectionWS = IntersectPositionWS - CubemapPositionWS;
  // The capture point may be anywhere inside the box (the Enlighten documentation: "allows the cube
  // map centre to be different to the centre of the box").
  Lookup out;
  const glm::vec3 rayLS = unitFromWorld * r;
  const glm::vec3 xLS = unitFromWorld * (x - boxCenter);
  if (rayLS == glm::vec3(0.0f)) return out;
  if (glm::any(glm::greaterThan(glm::abs(xLS), glm::vec3(1.0f) + toleranceUnit))) return out;
  const glm::vec3 unitary(1.0f);
  const glm::vec3 first = (unitary - xLS) / rayLS;
  const glm::vec3 second = (-unitary - xLS) / rayLS;
  glm::vec3 furthest;
  for (int i = 0; i < 3; ++i) furthest[i] = rayLS[i] != 0.0f ? hmax(first[i], second[i]) : kInf;
  const float distance = hmin(furthest.x, hmin(furthest.y, furthest.z));
  return finish(x - capture, r, hmax(0.0f, distance));
}

Lookup convex(std::span<const glm::vec4> planes, glm::vec3 capture, glm::vec3 x, glm::vec3 r) {
  // Lagarde & Zanuttini's convex volumes, the box code generalized to k planes (the Enlighten
  // documentation's form: "6 ray-plane intersections ... back-face cull 3 of the planes ... pick
  // the closest"):
  //   rayPlane = (offset - dot(n, PositionWS)) / dot(n, ReflDirectionWS), front-facing only;
  //   Distance = min over front-facing planes.
  Lookup out;
  if (r == glm::vec3(0.0f)) return out;
  float distance = kInf;
  for (const glm::vec4& plane : planes) {
    const glm::vec3 n(plane);
    const float toPlane = plane.w - glm::dot(n, x);  // >= 0 inside
    if (toPlane < -kTolerance) return out;           // outside this plane: red
    const float towards = glm::dot(n, r);
    if (towards > 0.0f) distance = hmin(distance, hmax(0.0f, toPlane) / towards);
  }
  return finish(x - capture, r, distance);
}

}  // namespace probeproxy::seed
