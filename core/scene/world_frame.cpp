#include "core/scene/world_frame.h"

#include <glm/gtc/constants.hpp>

namespace probeproxy {

namespace {
// The rotation that takes Y-up coordinates to Z-up ones: +90 degrees about X.
const glm::dquat kZUpFromYUp = glm::angleAxis(glm::half_pi<double>(), glm::dvec3(1, 0, 0));
}  // namespace

glm::dquat zUpFromYUp(const glm::dquat& rotationInYUp) {
  return kZUpFromYUp * rotationInYUp * glm::conjugate(kZUpFromYUp);
}

glm::dquat yUpFromZUp(const glm::dquat& rotationInZUp) {
  return glm::conjugate(kZUpFromYUp) * rotationInZUp * kZUpFromYUp;
}

}  // namespace probeproxy
