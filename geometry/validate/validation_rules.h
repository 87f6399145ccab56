#pragma once
// The rules behind validateScene (validate_scene.h), one function each, so a test can run one
// rule alone. Each appends its findings to `out`.

#include "core/proxy/proxy_shape.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/validate/validate_scene.h"

#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <vector>

namespace probeproxy {

// The walkable floor (geometry/floor/walkable_floor.h) reached from options.seedPointsMeters, or
// from the scene's capture points when there are none, on a grid of options.gridSpacingMeters.
// Empty when there is no seed.
WalkableFloor walkedFloor(const Scene& scene, const LevelRayCaster& level,
                          const ValidateOptions& options);

// Per probe.
void checkAuthoredMesh(const Scene& scene, const Probe& probe, std::vector<ValidationFinding>& out);
void checkCaptureInsideProxy(const Probe& probe, const ProxyShape& authored,
                             std::vector<ValidationFinding>& out);
void checkCaptureInsideInfluence(const Probe& probe, std::vector<ValidationFinding>& out);
void checkCaptureInsideLevel(const LevelRayCaster& level, const Probe& probe,
                             std::vector<ValidationFinding>& out);
// With split_probe where neither the authored nor the generated proxy is within the tolerance.
// `volumes`: every probe's influence, in scene order (the blend the probe serves in);
// `probeIndex`: this probe's.
void checkProxyError(const LevelRayCaster& level, const Probe& probe,
                     std::span<const InfluenceVolume> volumes, int probeIndex,
                     const ProxyShape& authored, const std::vector<FloorCell>& floor,
                     const ValidateOptions& options, std::vector<ValidationFinding>& out);
// split_probe: whether a second capture point over the probe's floor, the volume split halfway
// between the two, brings `samples` (its mirror_floor samples) within the tolerance; `own` is
// the probe's best proxy, of p95 ownP95Deg. Names the best such point.
void checkSplitProbe(const LevelRayCaster& level, const Probe& probe, const ProxyShape& own,
                     double ownP95Deg, std::span<const ReflectionSample> samples,
                     const std::vector<FloorCell>& floor, const ValidateOptions& options,
                     std::vector<ValidationFinding>& out);
void checkInfluenceLeak(const LevelRayCaster& level, const Probe& probe,
                        const std::vector<FloorCell>& floor, const ValidateOptions& options,
                        std::vector<ValidationFinding>& out);
void checkReflectedCameras(const LevelRayCaster& level, const Probe& probe,
                           const ProxyShape& authored, const ValidateOptions& options,
                           std::vector<ValidationFinding>& out);

// Scene-wide.
// Both look where a camera can be (camera_space.h): over `walked`, the walked floor.
void checkOverlaps(const Scene& scene, const LevelRayCaster& level, const WalkableFloor& walked,
                   const ValidateOptions& options, std::vector<ValidationFinding>& out);
void checkInnerRanges(const Scene& scene, const ValidateOptions& options,
                      std::vector<ValidationFinding>& out);
void checkWeightJumps(const Scene& scene, const LevelRayCaster& level, const WalkableFloor& walked,
                      const ValidateOptions& options, std::vector<ValidationFinding>& out);
void checkFloorCoverage(const Scene& scene, const std::vector<FloorCell>& floor,
                        const ValidateOptions& options, std::vector<ValidationFinding>& out);

// How far a point lies outside a shape, metres (negative inside; -inf for shapes without a
// volume, which contain everything).
double metersOutside(const ProxyShape& shape, glm::dvec3 pointMeters);

// "(x, y, z)" with centimetre precision, for messages.
std::string formatPoint(glm::dvec3 pointMeters);

}  // namespace probeproxy
