#pragma once
// Diffuse lighting from a cubemap through spherical harmonics (Bjorke, GPU Gems ch. 19, and
// Lagarde's blog): the radiance projected onto the real SH basis up to band 1 (L1, 4 coefficients,
// Lagarde's blog's SH buffer) or band 2 (L2, 9 coefficients), and the irradiance of a surface with
// normal n (Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment
// Maps").
//
// Basis: world frame (Z up, so Z is the polar axis), unit direction (x, y, z), coefficient
// order (l, m) = (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) (2,1) (2,2), with the
// Condon-Shortley phase that Lagarde's blog's SHEvalDirection uses:
//   Y00 = 0.282095
//   Y1-1 = -0.488603 y   Y10 = 0.488603 z   Y11 = -0.488603 x
//   Y2-2 = 1.092548 xy   Y2-1 = -1.092548 yz   Y20 = 0.315392 (3z^2 - 1)
//   Y21 = -1.092548 xz   Y22 = 0.546274 (x^2 - y^2)
// So the first four coefficients of a channel are exactly Lagarde's blog's float4 (x, y, z, w) for
// that channel (SHLightr/g/b), and a light of radiant intensity I in direction l adds
// I * Y(l) to them as its AddLightToSH does. Ramamoorthi & Hanrahan write their basis without
// that phase; their irradiance formula is used below with the signs of Y1-1, Y11, Y2-1, Y21
// flipped to match.

#include "core/cube/cubemap.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace probeproxy {

enum class ShOrder { L1, L2 };  // 4 or 9 coefficients

inline constexpr int kShL2Count = 9;

// RGB coefficients of a radiance function, in the order above (L1 uses the first four).
struct ShRgb {
  std::array<glm::vec3, kShL2Count> coefficients{};
};

// The nine basis functions at a unit direction.
std::array<float, kShL2Count> shBasis(glm::vec3 unitDirection);

// L_lm = sum over texels of radiance * Y_lm(texel centre direction) * texel solid angle
// (core/cube/texel_solid_angle.h), accumulated in double. Constant radiance 1 gives
// L00 = 4 pi * 0.282095 = 2 sqrt(pi). Throws std::out_of_range on a missing level.
ShRgb projectCubemapToSh(const Cubemap& cube, int level = 0);

// The radiance the coefficients describe in a direction (any length, not zero):
// sum of L_lm Y_lm over the order's bands.
glm::vec3 evaluateSh(const ShRgb& sh, glm::vec3 direction, ShOrder order);

// Irradiance E(n) = integral of radiance * max(0, n . w) dw at a surface with normal n (any
// length, not zero), from the order's bands, with Ramamoorthi & Hanrahan's constants
//   c1 = 0.429043 c2 = 0.511664 c3 = 0.743125 c4 = 0.886227 c5 = 0.247708
// (= the clamped cosine's band factors pi, 2 pi / 3, pi / 4 times the basis constants).
// Constant radiance 1 gives pi. Divide by pi for the outgoing radiance of a white Lambertian
// surface.
glm::vec3 irradianceFromSh(const ShRgb& sh, glm::vec3 normal, ShOrder order);

// Lagarde's blog's L1 buffer: per colour channel (r, g, b) the float4 (L00, L1-1, L10, L11).
std::array<glm::vec4, 3> seedL1Buffer(const ShRgb& sh);

}  // namespace probeproxy
