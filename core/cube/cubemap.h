#pragma once
// A radiance cubemap: six linear float RGB faces for every mip level. Owns its texels.
//
// Faces, texel centres and directions follow core/cube/cube_face.h (the one convention, the
// same as the Blender renders). Level 0 is the sharpest, N x N texels; any N >= 1 works, a
// power of two or not.
//
// Mip chain (box filter): level l+1 has size max(1, floor(N_l / 2)) and runs down to 1 x 1, so
// a cube has floor(log2(N)) + 1 levels. Each texel of level l+1 is the area-weighted mean of
// the level-l texels its square covers: parent (c, r) covers the child span
// [c * N_l / N_{l+1}, (c + 1) * N_l / N_{l+1}) in each axis. For even N_l that is exactly the
// mean of the 2 x 2 children; for odd N_l the children on a span boundary count by the
// fraction covered, so every level still tiles the face uniformly, which sampling assumes.
// Faces are filtered independently (no filtering across seams).

#include "core/cube/cube_face.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace probeproxy {

struct CubemapLevel {
  int faceSize = 0;  // texels per face side at this level
  // rgb[face][(row * faceSize + col) * 3 + channel]: linear RGB (scene-referred radiance),
  // row 0 at the top of the face image.
  std::array<std::vector<float>, kCubeFaceCount> rgb;
};

struct Cubemap {
  std::vector<CubemapLevel> levels;  // levels[0] is the sharpest

  // Level 0 from six faces (face-index order, interleaved RGB, row 0 at the top), each
  // faceSize x faceSize. Only level 0: call buildMipChain() for the rest. Throws
  // std::invalid_argument on a size below 1, a face of the wrong length or a non-finite value.
  static Cubemap fromFaces(int faceSize, std::array<std::vector<float>, kCubeFaceCount> rgb);

  // Replaces levels 1.. with the box-filtered chain from level 0 (see above) down to 1 x 1.
  void buildMipChain();

  int numLevels() const { return static_cast<int>(levels.size()); }
  int faceSize(int level = 0) const { return levels.at(static_cast<std::size_t>(level)).faceSize; }

  // Texel (col, row) of a face at a level. Indices are checked (std::out_of_range).
  glm::vec3 texel(CubeFace face, int level, int col, int row) const;
};

// floor(log2(faceSize)) + 1: the length of a full chain for a level-0 size.
int fullMipCount(int faceSize);

}  // namespace probeproxy
