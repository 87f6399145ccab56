#pragma once
// The one cube-face convention of probeproxy. Every cubemap, depth cube, Blender render and
// export uses it; nothing else in the code base may hard-code a face axis.
//
// World frame: right-handed, Z up, metres (Blender's frame; scenes declared "Y"-up are
// converted on load, see core/scene/world_frame.h).
//
// Each face is the image a pinhole camera at the cube centre sees with a 90 degree field of
// view, looking along the face's `forward` axis with the face's `up` axis at the top of the
// image: a photograph, not mirrored, row 0 at the top. So a face opened in any image viewer
// looks like the room. Image right is forward x up.
//
//   face index  name  forward  up    right (= forward x up)
//   0           px    +X       +Z    -Y
//   1           nx    -X       +Z    +Y
//   2           py    +Y       +Z    +X
//   3           ny    -Y       +Z    -X
//   4           pz    +Z       +Y    -X     (looking at the ceiling, +Y at the top)
//   5           nz    -Z       -Y    -X     (looking at the floor, -Y at the top)
//
// Texel (col, row) of an N x N face has its centre at
//   u = (col + 0.5) / N,  v = (row + 0.5) / N        (u right, v down, both in [0, 1])
// and looks along  forward + (2u - 1) * right + (1 - 2v) * up   (not normalized).
//
// Files of a cube use the face names: `probe_{face}.exr` -> probe_px.exr ... probe_nz.exr.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace probeproxy {

enum class CubeFace : int { px = 0, nx = 1, py = 2, ny = 3, pz = 4, nz = 5 };

inline constexpr int kCubeFaceCount = 6;

struct CubeFaceAxes {
  glm::vec3 forward;  // unit, world frame
  glm::vec3 up;       // unit, world frame, top of the image
  glm::vec3 right;    // unit, world frame, = cross(forward, up)
};

// The table above, in face-index order.
const std::array<CubeFaceAxes, kCubeFaceCount>& cubeFaceAxes();

std::string_view cubeFaceName(CubeFace face);  // "px", "nx", ...

// Unnormalized world direction through the point (u, v) of a face (u right, v down, [0, 1]).
glm::vec3 directionFromFaceUv(CubeFace face, glm::vec2 uv);

// Unit world direction through the centre of texel (col, row) of an N x N face.
glm::vec3 texelDirection(CubeFace face, int col, int row, int faceSize);

struct FaceUv {
  CubeFace face;
  glm::vec2 uv;  // u right, v down, in [0, 1]
};

// The face a direction falls on (largest absolute component; ties go to the lower face index)
// and where on it. A zero direction returns px at the centre.
FaceUv faceUvFromDirection(glm::vec3 direction);

}  // namespace probeproxy
