#include "geometry/pointcloud/probe_point_cloud.h"

#include "geometry/raycast/capture_depth_cube.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

PointCloud probePointCloud(const LevelRayCaster& level, const Cubemap& cube,
                           glm::dvec3 captureMeters) {
  const int n = cube.faceSize(0);
  const std::vector<RayHit> hits = castDepthCubeRays(level, captureMeters, n);
  const std::vector<Ray> rays = depthCubeRays(captureMeters, n);
  PointCloud cloud;
  cloud.originMeters = captureMeters;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const std::size_t i = (static_cast<std::size_t>(f) * n + row) * n + col;
        const RayHit& hit = hits[i];
        if (!hit.hit()) continue;
        const glm::vec3 d = glm::normalize(rays[i].direction);
        // A texel spans 2 / N of the face plane at unit distance (less off the face centre,
        // which this ignores: at most 1.7x too wide at the corners).
        const float cosIncidence = std::max(std::abs(glm::dot(d, hit.geometricNormal)), 0.2f);
        RadiancePoint p;
        p.fromOriginMeters = hit.t * d;
        p.normal = hit.geometricNormal;
        p.rgb = cube.texel(CubeFace(f), 0, col, row);
        p.radiusMeters = hit.t * (1.0f / static_cast<float>(n)) / std::sqrt(cosIncidence);
        cloud.points.push_back(p);
      }
    }
  }
  return cloud;
}

}  // namespace probeproxy
