#pragma once
// Filtered lookups into a Cubemap (core/cube/cubemap.h) and the roughness-to-mip mapping.

#include "core/cube/cubemap.h"

#include <glm/vec3.hpp>

namespace probeproxy {

// Seam-aware bilinear lookup at mip `level` (fractional: trilinear, linear between the two
// nearest levels; clamped to [0, numLevels - 1]). `direction` is in the world frame and need not
// be normalized; a zero direction looks at the centre of face px (cube_face.h).
//
// Within a face it is ordinary bilinear filtering between the four texel centres around the
// point. Where some of those four lie beyond the face edge (the outer half texel), each is
// fetched from the adjacent face: its centre, extended on the face plane, is turned into a
// direction and looked up there (faceUvFromDirection). At a cube corner the texel beyond both
// edges is the mean of the three corner texels that meet there. So the result is continuous
// across edges and corners; a gradient crossing a seam shows no step.
// Throws std::invalid_argument on an empty cubemap or a NaN level or direction.
glm::vec3 sampleBilinear(const Cubemap& cube, glm::vec3 direction, float level);

// The Enlighten documentation ("PBR reflections"): mip = numMips + 2 * log2(roughness), for a chain
// filtered by plain downsampling and shaded as if GGX-prefiltered. Clamped to
// [0, numMips - 1]; level 0 is the sharpest, so roughness 0 (log2 = -inf) gives 0 and
// roughness 1 gives numMips - 1. Throws std::invalid_argument on numMips < 1 or a NaN
// roughness.
float mipFromRoughness(float roughness, int numMips);

}  // namespace probeproxy
