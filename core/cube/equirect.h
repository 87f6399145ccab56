#pragma once
// Equirectangular (latitude-longitude, 2:1) images and cubemaps. Same orientation as
// Blender's world Environment Texture, so an HDRI looks the same in both:
//   pixel centre (u, v) in [0, 1] (u right, v down): longitude phi = (0.5 - u) * 2 pi,
//   latitude theta = (0.5 - v) * pi, direction = (cos theta cos phi, cos theta sin phi,
//   sin theta) in the world frame (Z up).
// So the image centre looks along +X, u = 0.75 along -Y (right of +X, as on face px), the
// left and right edges along -X, the top row at +Z (zenith), the bottom row at -Z.

#include "core/cube/cubemap.h"
#include "core/image/rgb_image.h"

namespace probeproxy {

// The direction through the point (u, v) of an equirectangular image (unit, world frame).
glm::vec3 equirectDirection(float u, float v);

// Level 0 of an N x N cube: each texel is the equirect image bilinearly sampled at its centre
// direction (wrapping in longitude, clamped at the poles). Point sampling: an image much
// larger than 4N x 2N aliases; faceSize = width / 4 keeps the equator's texel density.
// Throws std::invalid_argument on faceSize < 1 or an empty or wrongly sized image.
Cubemap cubeFromEquirect(const RgbImage& image, int faceSize);

// A width x width/2 equirect image of one mip level, each pixel sampled with sampleBilinear
// (seam-aware) at its centre direction. Throws std::invalid_argument on width < 2 or odd,
// std::out_of_range on a missing level.
RgbImage equirectFromCube(const Cubemap& cube, int width, int level = 0);

}  // namespace probeproxy
