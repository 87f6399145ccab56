#include "core/parallax/prepared_proxy.h"

#include "core/parallax/reference_lookup.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace probeproxy {

namespace {

// v rounded to float and back. The volatile is deliberate: GCC 12.2 at -O2/-O3 was seen to
// drop the round trip dvec3 -> vec3 -> dvec3 for the x and y components (SLP vectorized),
// which puts every constant a few millimetres off the float capture point far from the origin.
double roundedToFloat(double v) {
  volatile float f = static_cast<float>(v);
  return f;
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("prepareProxy: " + what);
}

}  // namespace

PreparedProxy prepareProxy(const ProxyShape& shape, glm::dvec3 captureMeters) {
  if (!finite(captureMeters)) fail("the capture point is not finite");
  // Every constant is relative to the float capture point c, the one x - C is taken from.
  const glm::dvec3 c(roundedToFloat(captureMeters.x), roundedToFloat(captureMeters.y),
                     roundedToFloat(captureMeters.z));
  const glm::vec3 captureF(c);
  PreparedProxy out;

  if (std::holds_alternative<InfiniteShape>(shape)) return out;

  if (const auto* k = std::get_if<CheapKShape>(&shape)) {
    if (!std::isfinite(k->kPerMeter)) fail("cheap_k's k is not finite");
    out.method = Method::CheapK;
    out.constants = CheapKConstants{captureF, static_cast<float>(k->kPerMeter)};
    return out;
  }

  if (const auto* s = std::get_if<SphereShape>(&shape)) {
    const glm::dvec3 radii = s->radiiMeters;
    if (!(radii.x > 0 && radii.y > 0 && radii.z > 0) || !finite(radii) || !finite(s->centerMeters))
      fail("the sphere's radii must be positive and finite");
    // lighting = diag(1 / radii) * sphereFromWorld * (x - centre)
    const glm::dmat3 sphereFromWorld = glm::mat3_cast(glm::conjugate(s->worldFromSphere));
    glm::dmat3 lightingFromWorld = sphereFromWorld;
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) lightingFromWorld[col][row] /= radii[row];
    SphereConstants sc;
    sc.captureMeters = captureF;
    sc.lightingFromWorld = glm::mat3(lightingFromWorld);
    sc.captureInLighting = glm::vec3(lightingFromWorld * (c - s->centerMeters));
    sc.insideToleranceLighting =
        static_cast<float>(kInsideToleranceMeters / std::max(radii.x, std::max(radii.y, radii.z)));
    out.method = Method::Sphere;
    out.constants = sc;
    return out;
  }

  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    const glm::dvec3 h = box->halfExtentsMeters;
    if (!(h.x > 0 && h.y > 0 && h.z > 0) || !finite(h) || !finite(box->centerMeters))
      fail("the box's half-extents must be positive and finite");
    if (methodOf(shape) == Method::Aabb) {
      out.method = Method::Aabb;
      out.constants = AabbConstants{captureF, glm::vec3(box->centerMeters - h - c),
                                    glm::vec3(box->centerMeters + h - c)};
      return out;
    }
    const glm::dmat3 boxFromWorld = glm::mat3_cast(glm::conjugate(box->worldFromBox));
    glm::dmat3 unitFromWorld = boxFromWorld;
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) unitFromWorld[col][row] /= h[row];
    out.method = Method::Obb;
    out.constants =
        ObbConstants{captureF, glm::mat3(unitFromWorld), glm::vec3(box->centerMeters - c),
                     glm::vec3(kInsideToleranceMeters / h)};
    return out;
  }

  const auto& convex = std::get<ConvexProxy>(shape);
  ConvexConstants cc;
  cc.captureMeters = captureF;
  for (const ProxyPlane& p : convex.planes) {
    if (!finite(p.normal) || !std::isfinite(p.offsetMeters) ||
        std::abs(glm::length(p.normal) - 1.0) > 1e-6) {
      std::ostringstream msg;
      msg << "convex plane " << cc.planesFromCapture.size()
          << " needs a unit normal and a finite offset";
      fail(msg.str());
    }
    cc.planesFromCapture.emplace_back(glm::vec3(p.normal),
                                      static_cast<float>(p.offsetMeters - glm::dot(p.normal, c)));
  }
  out.method = Method::Convex;
  out.constants = std::move(cc);
  return out;
}

seed::Lookup lookupScalar(const PreparedProxy& proxy, glm::vec3 x, glm::vec3 r) {
  // The seed ports take world-frame geometry; the prepared constants are relative to C, so the
  // ports get x - C and a capture point at the origin (a change of origin, the same maths).
  switch (proxy.method) {
    case Method::Infinite:
      return seed::infinite(r);
    case Method::CheapK: {
      const auto& k = std::get<CheapKConstants>(proxy.constants);
      return seed::cheapK(k.kPerMeter, glm::vec3(0.0f), x - k.captureMeters, r);
    }
    case Method::Sphere: {
      const auto& s = std::get<SphereConstants>(proxy.constants);
      glm::mat4 lightingFromCapture(s.lightingFromWorld);
      lightingFromCapture[3] = glm::vec4(s.captureInLighting, 1.0f);
      return seed::sphere(lightingFromCapture, s.insideToleranceLighting, glm::vec3(0.0f),
                          x - s.captureMeters, r);
    }
    case Method::Aabb: {
      const auto& b = std::get<AabbConstants>(proxy.constants);
      return seed::aabb(b.boxMinFromCapture, b.boxMaxFromCapture, glm::vec3(0.0f),
                        x - b.captureMeters, r);
    }
    case Method::Obb: {
      const auto& b = std::get<ObbConstants>(proxy.constants);
      return seed::obb(b.unitFromWorld, b.centerFromCapture, b.insideToleranceUnit, glm::vec3(0.0f),
                       x - b.captureMeters, r);
    }
    case Method::Convex: {
      const auto& cc = std::get<ConvexConstants>(proxy.constants);
      return seed::convex(cc.planesFromCapture, glm::vec3(0.0f), x - cc.captureMeters, r);
    }
  }
  return {};
}

void lookupBatch(const PreparedProxy& proxy, const RaysSoA& rays, const LookupsSoA& out) {
  const std::size_t n = rays.size();
  if (rays.yMeters.size() != n || rays.zMeters.size() != n || rays.dirX.size() != n ||
      rays.dirY.size() != n || rays.dirZ.size() != n || out.dirX.size() != n ||
      out.dirY.size() != n || out.dirZ.size() != n || out.miss.size() != n) {
    std::ostringstream msg;
    msg << "lookupBatch: every span must hold " << n << " values (dirX " << rays.dirX.size()
        << ", out.dirX " << out.dirX.size() << ", out.miss " << out.miss.size() << ")";
    throw std::invalid_argument(msg.str());
  }
  switch (proxy.method) {
    case Method::Infinite:
      return infiniteBatch(rays, out);
    case Method::CheapK:
      return cheapKBatch(std::get<CheapKConstants>(proxy.constants), rays, out);
    case Method::Sphere:
      return sphereBatch(std::get<SphereConstants>(proxy.constants), rays, out);
    case Method::Aabb:
      return aabbBatch(std::get<AabbConstants>(proxy.constants), rays, out);
    case Method::Obb:
      return obbBatch(std::get<ObbConstants>(proxy.constants), rays, out);
    case Method::Convex:
      return convexBatch(std::get<ConvexConstants>(proxy.constants), rays, out);
  }
}

}  // namespace probeproxy
