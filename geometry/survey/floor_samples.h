#pragma once
// The survey's reflection samples: mirror_floor views (reflection_samples.h's player view
// directions) spread area-uniform over the whole walkable floor, not per influence volume.
// Each floor cell gets the same number of samples at fixed-seed jittered points in it; each
// sample's camera stands back along its view direction at eye height, where it can see the
// point. True hits are traced; occlusion depends on the probe and is left to the blend.
// Deterministic whatever the thread count: every cell draws from its own seeded stream.

#include "geometry/evaluation/reflection_sample.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <cstdint>
#include <vector>

namespace probeproxy {

struct FloorSampleOptions {
  int samplesPerCell = 8;
  double eyeHeightMeters = 1.7;
  int maxViewAttempts = 16;  // then the camera looks straight down (89 degrees) at the point
  double upwardCosine = 0.7;
  double stepHeightMeters = 0.45;  // how far from the cell's height a jittered point may lie
  std::uint32_t seed = 1;
};

struct FloorSample {
  ReflectionSample sample;        // occluded is false: it is the blend's to decide, per probe
  std::size_t cell = 0;           // index into WalkableFloor::cells
  double areaSquareMeters = 0.0;  // the cell's area over its sample count
};

// What a sample costs a survey or a layout at its peak: itself (sizeof(FloorSample)) and its
// error, weights and map figures; fitted on the generated towns.
inline constexpr std::uint64_t kBytesPerSample = 192;

std::vector<FloorSample> buildFloorSamples(const LevelRayCaster& level, const WalkableFloor& floor,
                                           const FloorSampleOptions& options = {});

}  // namespace probeproxy
