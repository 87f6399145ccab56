#pragma once
// The cubemap lookup vector each correction method computes, in double precision and written
// for clarity: the reference that proxy fitting and error evaluation use, and that the fast
// shader-style kernels are checked against.
//
// For a shading point x with reflection direction r and a cubemap captured at C:
//   infinite: d = r
//   cheap_k:  d = k (x - C) + r                       (Lagarde & Zanuttini 2012)
//   proxies:  d = P - C, P = x + t r where the ray leaves the proxy
// A miss (the seeds' red pixel) is no value: x outside the proxy (beyond kInsideToleranceMeters),
// a ray that never leaves it (unbounded planes), a zero r, or P landing on C.

#include "core/proxy/proxy_shape.h"

#include <glm/vec3.hpp>

#include <optional>

namespace probeproxy {

// Shading points on a proxy's boundary (a floor the proxy was fitted to) count as inside.
inline constexpr double kInsideToleranceMeters = 1e-3;

std::optional<glm::dvec3> referenceLookup(const ProxyShape& shape, glm::dvec3 captureMeters,
                                          glm::dvec3 xMeters, glm::dvec3 r);

// Distance t >= 0 along r (in units of |r|) at which the ray from x leaves the shape; none for
// a miss. Infinite and cheap_k shapes have no boundary: none.
std::optional<double> exitDistance(const ProxyShape& shape, glm::dvec3 xMeters, glm::dvec3 r);

}  // namespace probeproxy
