#pragma once
// The angular error of a correction method over a probe's reflection samples.

#include "core/measures/error_figures.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/evaluation/reflection_sample.h"

#include <span>
#include <vector>

namespace probeproxy {

// angle(d, d*) in degrees for one visible sample; NaN for a miss. d* is H - C, or r when the
// ray leaves to the sky.
double angularErrorDeg(const ProxyShape& shape, glm::dvec3 captureMeters,
                       const ReflectionSample& s);

// One entry per sample that is not occluded, in sample order.
std::vector<double> angularErrorsDeg(const ProxyShape& shape, glm::dvec3 captureMeters,
                                     std::span<const ReflectionSample> samples);

ErrorFigures evaluateShape(const ProxyShape& shape, glm::dvec3 captureMeters,
                           std::span<const ReflectionSample> samples);

// The angle between two directions, accurate near zero (atan2 of sine and cosine).
double angleBetweenDeg(glm::dvec3 a, glm::dvec3 b);

}  // namespace probeproxy
