#pragma once
// One interface over the lookup methods of docs/methods_and_measures.md's "Methods" table that run
// per pixel: a PreparedProxy is built once per probe from its ProxyShape and capture point (float
// constants, relative to the capture point), then looked up one ray at a time (the seeds'
// scalar shader ports, seed_lookups.h) or many at a time (batched_lookups.h).

#include "core/parallax/batched_lookups.h"
#include "core/parallax/seed_lookups.h"
#include "core/proxy/proxy_shape.h"

#include <glm/vec3.hpp>

#include <string_view>
#include <variant>

namespace probeproxy {

struct PreparedProxy {
  Method method = Method::Infinite;
  // The constants of `method` (std::monostate for infinite).
  std::variant<std::monostate, CheapKConstants, SphereConstants, AabbConstants, ObbConstants,
               ConvexConstants>
      constants;
};

// The method is methodOf(shape) (a box with the identity rotation is aabb). The capture
// point is rounded to float first and every constant is taken relative to that float point.
// Throws std::invalid_argument for a degenerate shape (a zero radius or half-extent, a plane
// normal that is not unit length) or a non-finite capture point.
PreparedProxy prepareProxy(const ProxyShape& shape, glm::dvec3 captureMeters);

// One ray: x in world metres, r any length. Same result as referenceLookup up to float
// rounding; misses are flagged, never NaN or inf.
seed::Lookup lookupScalar(const PreparedProxy& proxy, glm::vec3 xMeters, glm::vec3 r);

// Many rays. Throws std::invalid_argument unless every input and output span has the same
// length.
void lookupBatch(const PreparedProxy& proxy, const RaysSoA& rays, const LookupsSoA& out);

}  // namespace probeproxy
