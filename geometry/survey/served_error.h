#pragma once
// A probe's proxy judged on the floor it serves in the blend: each of its mirror_floor samples
// counts by the probe's blend weight there (Lagarde's, over every volume that reaches it), so
// floor a neighbour carries counts for little or nothing. `validate` holds an authored proxy to
// it against the generated one, and `layout` holds its own choice to it, by the same rule
// (servesClearlyBetter), so that validate never tells a layout to take a proxy the layout
// refused.

#include "core/proxy/proxy_shape.h"
#include "core/scene/influence_volume.h"
#include "geometry/evaluation/reflection_sample.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

struct ServedError {
  double p95Deg = 0.0;     // weighted, a miss at 180 degrees; NaN: no weighted visible sample
  double overShare = 0.0;  // weighted share over the tolerance, misses included
};

// The blend weight of volumes[probeIndex] at each sample's floor point (0 where it does not
// reach). Only the volumes covering a point weigh there: any subset of a scene's volumes that
// holds every one reaching the probe's, in the scene's order, gives the scene's weights.
std::vector<double> servedWeights(std::span<const InfluenceVolume> volumes, int probeIndex,
                                  std::span<const ReflectionSample> samples);

ServedError servedError(const ProxyShape& shape, glm::dvec3 captureMeters,
                        std::span<const ReflectionSample> samples, std::span<const double> weights,
                        double toleranceDeg);

// `a` serves the floor clearly better than `b`: at least kClearlyLessServedFloor less of it over
// the tolerance (a build fits on samples of its own, so a smaller difference is noise), with a
// p95 no worse by more than select_proxy.h's noise (2% + 0.05 degrees). Fewer small errors
// bought with more gross ones is no gain where a map's p95 lies. Where `b`'s tail is gross
// already (its p95 kGrossTailDeg or more: misses and lookups past a right angle, the wrong
// thing shown either way), the floor over the tolerance decides alone: aneurysm's probe_008 kept
// an obb leaving 85% of its served floor over 5 deg (p95 112 deg) against a convex fit's 31%
// (p95 a miss), and that corridor was a tenth of the map's worst floor.
inline constexpr double kClearlyLessServedFloor = 0.02;  // share of the served floor's weight
inline constexpr double kGrossTailDeg = 90.0;
bool servesClearlyBetter(const ServedError& a, const ServedError& b);

}  // namespace probeproxy
