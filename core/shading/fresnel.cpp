#include "core/shading/fresnel.h"

#include <algorithm>
#include <cmath>

namespace probeproxy {

float fresnelSchlick(float f0, float cosTheta) {
  const float m = 1.0f - std::min(std::abs(cosTheta), 1.0f);
  const float m2 = m * m;
  return f0 + (1.0f - f0) * (m2 * m2 * m);
}

}  // namespace probeproxy
