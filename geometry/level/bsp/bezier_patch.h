#pragma once
// Tessellation of a Quake 3 Bezier patch: a grid of width x height control points (both odd,
// at least 3), read as (width-1)/2 x (height-1)/2 biquadratic Bezier pieces that share their
// border rows. Each piece is cut into `subdivisions` x `subdivisions` quads, two triangles
// each. The pieces' shared borders are evaluated once, as one grid of points, so the
// tessellation is watertight within its own grid (not against neighbouring faces: the
// engine's own fix-up of those cracks, which welds patch edges to its neighbours' LOD, is
// not reproduced).

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

struct TessellatedPatch {
  std::vector<glm::dvec3> points;     // ((width-1)/2*s + 1) x ((height-1)/2*s + 1), row-major
  std::vector<glm::uvec3> triangles;  // indices into points; wound as the control grid is
};

// `controlPoints` is row-major (x fastest), width * height of them; `subdivisions` >= 1.
// The caller checks the sizes (the BSP reader names the face that is wrong).
TessellatedPatch tessellateBezierPatch(std::span<const glm::dvec3> controlPoints, int width,
                                       int height, int subdivisions);

}  // namespace probeproxy
