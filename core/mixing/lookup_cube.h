#pragma once
// What a mixing-step correction computes before any texel is sampled: for every texel of a cube
// centred at the reflected camera E', the lookup vector into the probe's cubemap. Both mixing
// methods (mixing_plane per texel, raster_convex by rasterization) produce one; sampling it is
// corrected_cubemap.h's job. World frame, metres. Owns its arrays.

#include "core/cube/cube_face.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace probeproxy {

struct LookupCube {
  int faceSize = 0;  // texels per face side
  // lookupMeters[face][row * faceSize + col] = P - C: P where the ray from E' through the texel
  // centre (cube_face.h) leaves the proxy, C the capture point. (0, 0, 0) on a miss.
  std::array<std::vector<glm::dvec3>, kCubeFaceCount> lookupMeters;
  // miss[face][row * faceSize + col] = 1 where the ray never leaves the proxy (it misses it, or
  // the proxy lies behind E'): the seed's red texel.
  std::array<std::vector<std::uint8_t>, kCubeFaceCount> miss;
};

// An empty cube of the given size: every texel a miss. Throws std::invalid_argument for a
// size below 1.
LookupCube emptyLookupCube(int faceSize);

// Direction (double precision, not normalized) through the centre of texel (col, row): the
// cube_face.h convention, forward + (2u - 1) right + (1 - 2v) up.
glm::dvec3 texelRayDirection(CubeFace face, int col, int row, int faceSize);

}  // namespace probeproxy
