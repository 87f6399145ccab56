#include "geometry/evaluation/evaluate_shape.h"

#include "core/errors/invariant_checks.h"
#include "core/parallax/reference_lookup.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace probeproxy {

double angleBetweenDeg(glm::dvec3 a, glm::dvec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * (180.0 / M_PI);
}

double angularErrorDeg(const ProxyShape& shape, glm::dvec3 capture, const ReflectionSample& s) {
  // Samples are built with unit reflection vectors; the sky's ideal lookup is r itself.
  PROBEPROXY_DCHECK(std::abs(glm::length(s.reflected) - 1.0) < 1e-9);
  const std::optional<glm::dvec3> d = referenceLookup(shape, capture, s.xMeters, s.reflected);
  if (!d) return std::numeric_limits<double>::quiet_NaN();
  const glm::dvec3 ideal = s.hitsSky ? s.reflected : s.trueHitMeters - capture;
  return angleBetweenDeg(*d, ideal);
}

std::vector<double> angularErrorsDeg(const ProxyShape& shape, glm::dvec3 capture,
                                     std::span<const ReflectionSample> samples) {
  std::vector<double> errors;
  errors.reserve(samples.size());
  for (const ReflectionSample& s : samples) {
    if (!s.occluded) errors.push_back(angularErrorDeg(shape, capture, s));
  }
  return errors;
}

ErrorFigures evaluateShape(const ProxyShape& shape, glm::dvec3 capture,
                           std::span<const ReflectionSample> samples) {
  std::vector<double> errors = angularErrorsDeg(shape, capture, samples);
  const std::size_t occluded = samples.size() - errors.size();
  return summarizeErrors(std::move(errors), occluded);
}

}  // namespace probeproxy
