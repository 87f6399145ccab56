#pragma once
// Proxies with one free parameter, each fitted to a probe's reflection samples by minimizing
// the mean sample cost (sample_cost.h).

#include "core/proxy/proxy_shape.h"
#include "geometry/evaluation/reflection_sample.h"

#include <span>

namespace probeproxy {

// Lagarde & Zanuttini's lookup = normalize(k (x - C) + r): the k that suits this probe's samples,
// searched over [0, 4 / nearest wall] (k = 1/R makes it exact for a sphere of radius R
// around C seen from C).
CheapKShape fitCheapK(glm::dvec3 captureMeters, std::span<const ReflectionSample> samples,
                      double typicalDistanceMeters);

// A sphere centred on the capture point: the radius that suits the samples best, searched
// between the nearest and the farthest level point the probe sees.
SphereShape fitCaptureSphere(glm::dvec3 captureMeters, std::span<const ReflectionSample> samples,
                             double nearestMeters, double farthestMeters);

}  // namespace probeproxy
