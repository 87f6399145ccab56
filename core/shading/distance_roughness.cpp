#include "core/shading/distance_roughness.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy {

// Why sqrt of the distance ratio:
// 1. Cone from roughness. The Enlighten documentation picks mip = numMips + 2 log2(roughness) from
// a chain built
//    by halving; a texel of mip m spans 2^m level-0 texels, i.e. an angle proportional to
//    2^m / N = 2^numMips roughness^2 / N, with numMips about log2(N) + 1. So the mip mapping
//    treats the lobe's cone as having tan(halfAngle) = k * roughness^2 (k a constant of the
//    chain: GGX's alpha = roughness^2 is the lobe width, the usual reading).
// 2. Footprint. The cone from x reaches P at distance |P - x|; there it covers a disc (take a
//    ball, so the angle it is seen at does not depend on the wall's slope) of radius
//    rho = |P - x| * tan(halfAngle).
// 3. Seen from C, that ball subtends tan(halfAngleC) = rho / |P - C|
//    = tan(halfAngle) * |P - x| / |P - C|.
// 4. Back to roughness: k * roughnessC^2 = k * roughness^2 * |P - x| / |P - C|, so
//    roughnessC = roughness * sqrt(|P - x| / |P - C|); k cancels, so the result does not
//    depend on the chain's size. Clamped to [0, 1], the range mipFromRoughness maps.
float roughnessSeenFromCapture(float roughness, float hitFromShadingMeters,
                               float hitFromCaptureMeters) {
  if (std::isnan(roughness) || std::isnan(hitFromShadingMeters) ||
      std::isnan(hitFromCaptureMeters)) {
    return std::numeric_limits<float>::quiet_NaN();
  }
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  if (r == 0.0f) return 0.0f;  // a mirror has no footprint, whatever the distances
  const float fromShading = std::max(hitFromShadingMeters, 0.0f);
  const float fromCapture = std::max(hitFromCaptureMeters, 0.0f);
  // ratio >= 1 / r^2 already clamps to 1; comparing first keeps P = C (0 / 0) and huge
  // ratios away from the division.
  if (fromShading >= fromCapture / (r * r)) return 1.0f;
  return std::min(r * std::sqrt(fromShading / fromCapture), 1.0f);
}

float roughnessSeenFromCapture(float roughness, glm::vec3 shadingMeters, glm::vec3 proxyHitMeters,
                               glm::vec3 captureMeters) {
  return roughnessSeenFromCapture(roughness, glm::distance(proxyHitMeters, shadingMeters),
                                  glm::distance(proxyHitMeters, captureMeters));
}

}  // namespace probeproxy
