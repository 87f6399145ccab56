#pragma once
// The proxy an artist authored in the scene file, as a shape the evaluation can measure.

#include "core/proxy/proxy_shape.h"
#include "core/scene/scene.h"
#include "geometry/level/level_mesh.h"

#include <optional>

namespace probeproxy {

// None for `auto`; InfiniteShape for `infinite`. A convex mesh is read like a level mesh (the
// scene's units; glTF Y-up) and turned into one plane per distinct face plane; whether it
// really is convex and closed is for the proxy mesh checks to say.
std::optional<ProxyShape> authoredProxyShape(const ProxySpec& spec, const Scene& scene);

// Whether a scene file can author `shape` (infinite, cheap_k, box/obb, sphere, convex mesh):
// not an ellipsoid. What layout writes into its scene must be one, or `build` and `survey` on
// that scene would make and measure another.
bool sceneFileCanHold(const ProxyShape& shape);

// The shapes layout chooses among when it fits a proxy to a range (ProxyBuildOptions::
// layoutShapesOnly): those a scene file can hold but cheap_k (proxy_build_options.h says why).
bool layoutChoosesAmong(const ProxyShape& shape);

// The authored convex mesh as it is in the file, in the world frame: what authoredProxyShape
// turns into planes and what the proxy mesh checks inspect.
LevelMesh loadAuthoredProxyMesh(const AuthoredConvexMesh& mesh, const Scene& scene);

// Planes of a triangle mesh wound counter-clockwise from outside, near-duplicates merged.
ConvexProxy convexFromMesh(std::vector<glm::dvec3> verticesMeters,
                           std::vector<glm::uvec3> triangles);

}  // namespace probeproxy
