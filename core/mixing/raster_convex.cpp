#include "core/mixing/raster_convex.h"

#include "core/raster/face_rasterizer.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace probeproxy {

namespace {

bool isFinite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The near plane sits a millionth of the proxy's size in front of E': close enough that only an
// exit point within that distance of E' (E' on the proxy's boundary) can be clipped, far enough
// that projected coordinates stay well inside double precision.
double nearPlaneMeters(const ConvexProxy& proxy, glm::dvec3 eye) {
  return std::max(1e-6 * farthestCornerMeters(proxy, eye), 1e-12);
}

}  // namespace

LookupCube rasterConvexLookups(const ConvexProxy& proxy, glm::dvec3 capture,
                               glm::dvec3 reflectedCamera, int faceSize) {
  if (proxy.triangles.empty())
    throw std::invalid_argument("raster_convex: the proxy has no triangles");
  if (!isFinite(capture) || !isFinite(reflectedCamera))
    throw std::invalid_argument("raster_convex: capture point and camera must be finite");
  for (const glm::dvec3& v : proxy.verticesMeters)
    if (!isFinite(v)) throw std::invalid_argument("raster_convex: a proxy vertex is not finite");

  // Culling: the triangle's outward normal (counter-clockwise from outside, convex_proxy.h)
  // must point away from E'. Decided once for all six faces.
  std::vector<std::array<RasterVertex, 3>> backFaces;
  for (const glm::uvec3& t : proxy.triangles) {
    const glm::dvec3 a = proxy.verticesMeters.at(t.x), b = proxy.verticesMeters.at(t.y),
                     c = proxy.verticesMeters.at(t.z);
    const glm::dvec3 outward = glm::cross(b - a, c - a);
    if (!(glm::dot(outward, a - reflectedCamera) > 0)) continue;
    backFaces.push_back(
        {RasterVertex{a, a - capture}, RasterVertex{b, b - capture}, RasterVertex{c, c - capture}});
  }

  const double nearMeters = nearPlaneMeters(proxy, reflectedCamera);
  LookupCube cube = emptyLookupCube(faceSize);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    FaceTarget target = emptyFaceTarget(faceSize);
    for (const auto& triangle : backFaces)
      rasterizeTriangle(static_cast<CubeFace>(f), reflectedCamera, nearMeters, triangle, target);
    for (std::size_t i = 0; i < target.covered.size(); ++i) {
      if (!target.covered[i] || target.attribute[i] == glm::dvec3(0.0)) continue;
      cube.lookupMeters[f][i] = target.attribute[i];
      cube.miss[f][i] = 0;
    }
  }
  return cube;
}

}  // namespace probeproxy
