#pragma once
// A small software rasterizer for one cube face: the face is a 90-degree pinhole camera at an
// eye point (core/cube/cube_face.h: forward, up, right; row 0 at the top), and triangles are
// drawn into it the way a GPU does, so the mixing step can be done "by rasterizing the proxy"
// as Lagarde & Zanuttini 2012 does on the console:
//   - near-plane clipping in camera space (nothing behind the eye is drawn),
//   - coverage at texel centres with the top-left fill rule (Direct3D's: a centre exactly on an
//     edge belongs to a triangle only if that edge is a top or a left edge), so triangles that
//     share an edge cover each texel along it exactly once,
//   - a per-vertex attribute interpolated perspective-correctly (linear in world space on the
//     triangle, not in screen space),
//   - the first triangle to cover a texel keeps it (no depth test: the caller draws a convex
//     proxy's back faces only, which never overlap).

#include "core/cube/cube_face.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace probeproxy {

struct RasterVertex {
  glm::dvec3 positionMeters{0.0};  // world frame
  glm::dvec3 attribute{
      0.0};  // anything linear in world space (Lagarde & Zanuttini 2012: vertex - C)
};

// One face's render target. Owns its texels; row-major, row 0 at the top.
struct FaceTarget {
  int faceSize = 0;
  std::vector<glm::dvec3> attribute;  // faceSize * faceSize
  std::vector<std::uint8_t> covered;  // 1 where a triangle wrote the texel
};

FaceTarget emptyFaceTarget(int faceSize);

// Camera space of a face seen from `eyeMeters`: x along right, y along up, z along forward.
// Points with z < nearMeters are clipped away. `nearMeters` must be positive.
void rasterizeTriangle(CubeFace face, glm::dvec3 eyeMeters, double nearMeters,
                       const std::array<RasterVertex, 3>& triangle, FaceTarget& target);

}  // namespace probeproxy
