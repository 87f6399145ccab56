#include "geometry/probe_proxies/probe_view.h"

#include "core/cube/depth_cube.h"
#include "geometry/probe_proxies/room_box.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/tune/visible_surface_planes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

std::vector<glm::dvec3> seenPoints(const DepthCube& cube) {
  std::vector<glm::dvec3> points;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < cube.faceSize; ++row) {
      for (int col = 0; col < cube.faceSize; ++col) {
        const float t = cube.at(CubeFace(f), col, row);
        if (std::isfinite(t)) {
          points.push_back(cube.captureMeters +
                           double(t) *
                               glm::dvec3(texelDirection(CubeFace(f), col, row, cube.faceSize)));
        }
      }
    }
  }
  return points;
}

}  // namespace

ProbeView seeLevel(const LevelRayCaster& level, glm::dvec3 capture, int faceSize) {
  ProbeView view;
  view.captureMeters = capture;
  // The rays kept: the back-face share below needs their directions.
  const std::vector<Ray> rays = depthCubeRays(capture, faceSize);
  view.hits.resize(rays.size());
  level.firstHits(rays, view.hits, /*coherent=*/true);
  view.pointsMeters = seenPoints(depthCubeFromHits(view.hits, capture, faceSize));
  view.skyShare =
      1.0 - static_cast<double>(view.pointsMeters.size()) / static_cast<double>(view.hits.size());
  std::size_t back = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const RayHit& h = view.hits[i];
    if (h.hit() && glm::dot(glm::dvec3(h.geometricNormal), glm::dvec3(rays[i].direction)) > 0.0)
      ++back;
  }
  view.backShare = static_cast<double>(back) / static_cast<double>(view.hits.size());
  if (!view.pointsMeters.empty()) {
    view.nearestMeters = 1e300;
    view.farthestMeters = 0.0;
    for (const glm::dvec3& p : view.pointsMeters) {
      const double d = glm::distance(p, capture);
      view.nearestMeters = std::min(view.nearestMeters, d);
      view.farthestMeters = std::max(view.farthestMeters, d);
    }
  }
  view.toleranceMeters = 1e-4 * std::max(view.farthestMeters, 1e-3) + 1e-4;
  // The planes of the walls the probe sees, exact where the hull's facets tilt by a texel.
  view.wallPlanes = visibleSurfacePlanes(view.hits, capture, faceSize, 10 * view.toleranceMeters);
  view.axisWallsMeters = axisWallDistances(level, capture);
  return view;
}

}  // namespace probeproxy
