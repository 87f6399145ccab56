#pragma once
// Building a probe's reflection sample sets against the level (Embree). Deterministic: the
// same level, probe, set and options give the same samples, whatever the thread count.

#include "core/scene/probe.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/floor/floor_graph.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <memory>
#include <optional>
#include <vector>

namespace probeproxy {

struct ReflectionSampleOptions {
  std::size_t targetSamples = 2048;  // stops here, or after maxAttemptsPerSample x this rays
  int maxAttemptsPerSample = 16;
  double eyeHeightMeters = 1.7;  // camera height above the floor under it
  int camerasAcross = 8;         // grid cells along the influence volume's longer side
  double minCameraSpacingMeters = 0.25;
  double upwardCosine = 0.9;  // mirror_floor: normal.z at least this (about 25 degrees)
  std::uint32_t seed = 1;
  // Cameras stand, and mirror_floor samples lie, only on floor a player can walk to from the
  // capture point within the influence volume (geometry/floor/walkable_floor.h): a 10 m sphere
  // around a spawn point in a real map reaches through walls into rooms the probe cannot see,
  // and a proxy fitted to their reflections is fitted to the wrong room. Where no such floor
  // is found (a probe over a void) every floor in the volume counts, as without it. The proxy
  // build fits on these; what a player sees (and every reported figure) is all the floor the
  // influence covers, as the runtime shades it.
  bool connectedFloorOnly = false;
  // The level's floor graph (floor_graph.h, built with default WalkableFloorOptions), when the
  // caller builds many probes on one level: the served floor is then a flood fill in it
  // instead of a new walkable floor. Same floor, on the level's grid instead of the probe's.
  std::shared_ptr<const FloorGraph> floorGraph;

  // Throws InputError unless targetSamples ("samples") is in [64, 1000000] and the rest is
  // usable (maxAttemptsPerSample >= 1, eye height and camera spacing positive).
  void check() const;
};

std::vector<ReflectionSample> buildReflectionSamples(const LevelRayCaster& level,
                                                     const Probe& probe, SampleSet set,
                                                     const ReflectionSampleOptions& options = {});

// buildReflectionSamples with the served floor already found (servedFloor with the same
// options), so the sets one probe draws share it.
std::vector<ReflectionSample> buildReflectionSamples(const LevelRayCaster& level,
                                                     const Probe& probe, SampleSet set,
                                                     const ReflectionSampleOptions& options,
                                                     const std::optional<WalkableFloor>& served);

// The cameras of the grid: at eye height above the floor, inside the influence volume. Falls
// back to the capture point when no grid point qualifies (a closet, a probe over a void).
std::vector<glm::dvec3> reflectionCameras(const LevelRayCaster& level, const Probe& probe,
                                          const ReflectionSampleOptions& options);

// The floor the probe serves (connectedFloorOnly): walkable from the capture point within the
// influence volume's bounds. Nothing when the option is off or no floor is found.
std::optional<WalkableFloor> servedFloor(const LevelRayCaster& level, const Probe& probe,
                                         const ReflectionSampleOptions& options);

// reflectionCameras with the served floor already found.
std::vector<glm::dvec3> reflectionCameras(const LevelRayCaster& level, const Probe& probe,
                                          const ReflectionSampleOptions& options,
                                          const std::optional<WalkableFloor>& floor);

// A view direction a player at eye height looks at the floor with (unit, pointing down), from
// three uniform numbers in [0, 1): the mirror_floor distribution, shared with `survey`.
glm::dvec3 playerFloorDirection(double uLook, double uDepression, double uHeading);

// Sets s.trueHitMeters and s.hitsSky from s.xMeters, s.normal and s.reflected (leaves
// s.occluded alone: that depends on the probe).
void traceTrueHit(const LevelRayCaster& level, ReflectionSample& s);

// Whether the capture point cannot see s's true hit (or the sky along r): the cubemap cannot
// show it, whatever the proxy. Needs traceTrueHit first.
bool trueHitHiddenFrom(const LevelRayCaster& level, glm::dvec3 captureMeters,
                       const ReflectionSample& s);

}  // namespace probeproxy
