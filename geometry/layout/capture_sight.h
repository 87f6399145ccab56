#pragma once
// Which floor samples a capture point could serve: those whose true hit it sees (the sky along
// the reflected ray for a sky sample), as reflection_samples.h's trueHitHiddenFrom decides, for
// every sample of the level at once. A candidate is judged on all of them, however far: a probe
// in the middle of a hangar serves the whole hangar, and its cubemap's sharpness is the proxy
// error's business, not a distance cap's.
//
// One ray per sample per candidate would cost more than the candidate's proxy, so the
// candidate's own depth cube answers first: a true hit nearer than every texel around its
// direction is seen, one farther than every texel is hidden, and only the samples on a
// silhouette (or on a face's edge) get a ray. Deterministic: the cube and the rays are.

#include "geometry/layout/index_set.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/floor_samples.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace probeproxy {

inline constexpr int kSightFaceSize = 64;  // texels 1.4 degrees across: few samples need a ray

struct CaptureSight {
  IndexSet seen;             // indices into the floor samples
  std::size_t raysCast = 0;  // samples the depth cube left undecided
};

// `maxDistanceMeters`: samples whose floor point is farther are not considered (0: no limit).
CaptureSight captureSight(const LevelRayCaster& level, glm::dvec3 captureMeters,
                          std::span<const FloorSample> samples, double maxDistanceMeters = 0.0);

}  // namespace probeproxy
