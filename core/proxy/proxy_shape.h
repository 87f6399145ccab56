#pragma once
// Every proxy shape a correction method intersects reflection rays with. World frame (Z up),
// metres. A box with the identity rotation is the `aabb` method's, any other the `obb`'s.

#include "core/proxy/convex_proxy.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string_view>
#include <variant>

namespace probeproxy {

struct InfiniteShape {};  // no proxy: the cubemap is looked up with the reflection vector

struct CheapKShape {  // Lagarde & Zanuttini's approximation: lookup = normalize(k * (x - C) + r)
  double kPerMeter = 0.0;
};

struct SphereShape {  // Bjorke's lighting-space sphere (an ellipsoid when radii differ)
  glm::dvec3 centerMeters{0.0};
  glm::dvec3 radiiMeters{1.0};  // along the sphere's own axes
  glm::dquat worldFromSphere{1, 0, 0, 0};
};

struct BoxShape {
  glm::dvec3 centerMeters{0.0};
  glm::dvec3 halfExtentsMeters{1.0};  // in the box's own frame
  glm::dquat worldFromBox{1, 0, 0, 0};
};

using ProxyShape = std::variant<InfiniteShape, CheapKShape, SphereShape, BoxShape, ConvexProxy>;

// The correction method a shader runs for a shape (docs/methods_and_measures.md "Methods"):
// the one vocabulary of lookups, in order from the simplest test. A box with the identity
// rotation is looked up as an aabb.
enum class Method { Infinite, CheapK, Sphere, Aabb, Obb, Convex };

Method methodOf(const ProxyShape& shape);

// The stable ids, for JSON and the command line only: "infinite", "cheap_k", "sphere", "aabb",
// "obb", "convex".
std::string_view methodName(Method method);
std::optional<Method> methodFromName(std::string_view name);

// methodName(methodOf(shape)), for reports.
std::string_view methodId(const ProxyShape& shape);

// Planes a shader tests: 0 for infinite, cheap_k and sphere, 6 for boxes, k for convex.
int planeCount(const ProxyShape& shape);

// Whether a point is strictly inside the shape (shapes without a volume contain everything):
// a capture point on or outside its proxy breaks parallax correction.
bool strictlyContains(const ProxyShape& shape, glm::dvec3 pointMeters);

// Whether every half-extent or radius of a box or sphere is finite and at least
// kThinnestShapeMeters (true for the shapes without one). A flat box, fitted to points in one
// plane or authored 2 um thick, divides a lookup by zero and is no engine's box.
inline constexpr double kThinnestShapeMeters = 1e-3;
bool holdsVolume(const ProxyShape& shape);

// The box as six planes and its 8 corners / 12 triangles.
ConvexProxy convexFromBox(const BoxShape& box);

}  // namespace probeproxy
