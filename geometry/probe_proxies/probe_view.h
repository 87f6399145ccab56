#pragma once
// Stage 1 of the proxy build: what the probe sees. The depth cube cast from the capture point,
// the level points it hits (sky texels have none), how near and far they are, the planes of
// the walls among them, and the tolerance the fits work to (relative to the room's size).

#include "core/proxy/convex_proxy.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace probeproxy {

struct ProbeView {
  glm::dvec3 captureMeters{0.0};
  std::vector<RayHit> hits;              // one per depth cube texel (castDepthCubeRays)
  std::vector<glm::dvec3> pointsMeters;  // the texels that hit the level
  double nearestMeters = 1.0;            // from the capture point; 1 when nothing is seen
  double farthestMeters = 1.0;
  double skyShare = 0.0;                    // texels that hit nothing
  double backShare = 0.0;                   // texels whose ray meets a surface from behind
  double toleranceMeters = 1e-4;            // hull tolerance: 1e-4 x farthest + 0.1 mm
  std::vector<ProxyPlane> wallPlanes;       // large planar surfaces seen (visibleSurfacePlanes)
  std::array<double, 6> axisWallsMeters{};  // room_box.h: walls along -x, +x, -y, +y, -z, +z
};

ProbeView seeLevel(const LevelRayCaster& level, glm::dvec3 captureMeters, int faceSize);

}  // namespace probeproxy
