#include "geometry/evaluation/reflection_samples.h"

#include "core/errors/option_checks.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace probeproxy {

void ReflectionSampleOptions::check() const {
  requireInRange<std::size_t>("samples", targetSamples, 64, 1'000'000);
  requireInRange("max_attempts_per_sample", maxAttemptsPerSample, 1, 1'000'000);
  requirePositive("eye_height_m", eyeHeightMeters);
  requireInRange("cameras_across", camerasAcross, 1, 10'000);
  requirePositive("min_camera_spacing_m", minCameraSpacingMeters);
  requireInRange("upward_cosine", upwardCosine, 0.0, 1.0);
}

std::string_view sampleSetName(SampleSet set) {
  return set == SampleSet::MirrorFloor ? "mirror_floor" : "all_surfaces";
}

namespace {

// Self-intersection offset. The ray caster works relative to the level's centre, so this need
// not grow with the distance from the world origin; a tenth of a millimetre suits rooms from a
// closet to a hangar.
double surfaceEpsilon(glm::dvec3) { return 1e-4; }

// all_surfaces: every direction alike.
glm::dvec3 uniformDirection(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double z = 2.0 * unit(rng) - 1.0;
  const double phi = 2.0 * M_PI * unit(rng);
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

RayHit castDouble(const LevelRayCaster& level, glm::dvec3 origin, glm::dvec3 direction,
                  double tMin = 0.0) {
  return level.firstHit({origin, glm::vec3(direction), static_cast<float>(tMin)});
}

glm::dvec3 drawPlayerFloorDirection(std::mt19937& rng) {
  // Three draws in a fixed order (not as call arguments, whose order C++ leaves open).
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double look = unit(rng);
  const double depression = unit(rng);
  const double heading = unit(rng);
  return playerFloorDirection(look, depression, heading);
}

}  // namespace

// mirror_floor: what a player at eye height sees of the floor. Mostly the camera looks level,
// in any direction, and the floor fills the lower half of a 90-degree-high view: a pixel row
// there is uniform in tan(depression) from 2 degrees (the far floor, where reflections graze)
// to 45. A quarter of the time the player looks down, uniform in angle from 45 to 89 degrees:
// in a closet that is the only floor there is to see.
glm::dvec3 playerFloorDirection(double uLook, double uDepression, double uHeading) {
  constexpr double kMinDepressionTan = 0.035;  // 2 degrees
  const bool lookingDown = uLook < 0.25;
  const double tanDepression = lookingDown
                                   ? std::tan((45.0 + 44.0 * uDepression) * M_PI / 180.0)
                                   : kMinDepressionTan + (1.0 - kMinDepressionTan) * uDepression;
  const double phi = 2.0 * M_PI * uHeading;
  return glm::normalize(glm::dvec3(std::cos(phi), std::sin(phi), -tanDepression));
}

void traceTrueHit(const LevelRayCaster& level, ReflectionSample& s) {
  // Skip the surface along r itself rather than shifting the origin off it: H then lies on the
  // very ray (x, r) that every proxy lookup intersects, so an exact proxy scores ~1e-6 degrees
  // instead of the ~0.002 degrees a 0.1 mm origin shift seen from a few metres would cost.
  const double eps = surfaceEpsilon(s.xMeters);
  const double tSkip = eps / std::max(glm::dot(s.reflected, s.normal), 1e-3);
  const RayHit hit = castDouble(level, s.xMeters, s.reflected, tSkip);
  s.hitsSky = !hit.hit();
  if (!s.hitsSky) s.trueHitMeters = s.xMeters + double(hit.t) * s.reflected;
}

bool trueHitHiddenFrom(const LevelRayCaster& level, glm::dvec3 capture, const ReflectionSample& s) {
  // The cubemap shows the sky along r only if nothing stands in the way from C.
  if (s.hitsSky) return castDouble(level, capture, s.reflected).hit();
  const glm::dvec3 toHit = s.trueHitMeters - capture;
  const double distance = glm::length(toHit);
  if (distance < 1e-9) return false;
  const RayHit fromCapture = castDouble(level, capture, toHit / distance);
  const double slack = 1e-3 * distance + surfaceEpsilon(s.trueHitMeters) * 10.0;
  return fromCapture.hit() && double(fromCapture.t) < distance - slack;
}

std::optional<WalkableFloor> servedFloor(const LevelRayCaster& level, const Probe& probe,
                                         const ReflectionSampleOptions& o) {
  if (!o.connectedFloorOnly) return std::nullopt;
  glm::dvec3 lo, hi;
  influenceBounds(probe.influence, lo, hi);
  WalkableFloorOptions floorOptions;
  floorOptions.regionMinMeters = glm::dvec2(lo);
  floorOptions.regionMaxMeters = glm::dvec2(hi);
  const glm::dvec3 seed[] = {probe.captureMeters};
  WalkableFloor floor = o.floorGraph
                            ? reachableFloor(*o.floorGraph, seed, floorOptions.regionMinMeters,
                                             floorOptions.regionMaxMeters)
                            : walkableFloor(level, seed, floorOptions);
  if (floor.cells.empty()) return std::nullopt;
  return floor;
}

namespace {

// A point on the floor counts when the probe's walkable floor reaches it (or there is none).
bool onServedFloor(const std::optional<WalkableFloor>& floor, glm::dvec3 pointMeters) {
  return !floor || floor->reaches(pointMeters, WalkableFloorOptions{}.stepHeightMeters);
}

}  // namespace

std::vector<glm::dvec3> reflectionCameras(const LevelRayCaster& level, const Probe& probe,
                                          const ReflectionSampleOptions& o) {
  return reflectionCameras(level, probe, o, servedFloor(level, probe, o));
}

std::vector<glm::dvec3> reflectionCameras(const LevelRayCaster& level, const Probe& probe,
                                          const ReflectionSampleOptions& o,
                                          const std::optional<WalkableFloor>& floor) {
  glm::dvec3 lo, hi;
  influenceBounds(probe.influence, lo, hi);
  const double longer = std::max(hi.x - lo.x, hi.y - lo.y);
  const double spacing = std::max(o.minCameraSpacingMeters, longer / o.camerasAcross);
  const int nx = std::max(1, static_cast<int>(std::floor((hi.x - lo.x) / spacing)));
  const int ny = std::max(1, static_cast<int>(std::floor((hi.y - lo.y) / spacing)));

  std::vector<glm::dvec3> cameras;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      // Cell centres, so a one-cell grid sits in the middle.
      const glm::dvec3 column(lo.x + (i + 0.5) * (hi.x - lo.x) / nx,
                              lo.y + (j + 0.5) * (hi.y - lo.y) / ny, probe.captureMeters.z);
      const RayHit below = castDouble(level, column, {0, 0, -1});
      if (!below.hit() || below.geometricNormal.z == 0.0f) continue;
      if (!onServedFloor(floor, column - glm::dvec3(0, 0, below.t))) continue;
      glm::dvec3 eye = column - glm::dvec3(0, 0, below.t) + glm::dvec3(0, 0, o.eyeHeightMeters);
      // Under a low ceiling (an attic's eaves, a closet) the eye goes halfway up instead.
      const RayHit ceiling =
          castDouble(level, column - glm::dvec3(0, 0, below.t - 1e-3), {0, 0, 1});
      if (ceiling.hit() && ceiling.t < o.eyeHeightMeters + 0.1) {
        eye.z = column.z - below.t + 0.5 * ceiling.t;
      }
      if (insideInfluence(probe.influence, eye)) cameras.push_back(eye);
    }
  }
  if (cameras.empty()) cameras.push_back(probe.captureMeters);
  return cameras;
}

std::vector<ReflectionSample> buildReflectionSamples(const LevelRayCaster& level,
                                                     const Probe& probe, SampleSet set,
                                                     const ReflectionSampleOptions& o) {
  return buildReflectionSamples(level, probe, set, o, servedFloor(level, probe, o));
}

std::vector<ReflectionSample> buildReflectionSamples(const LevelRayCaster& level,
                                                     const Probe& probe, SampleSet set,
                                                     const ReflectionSampleOptions& o,
                                                     const std::optional<WalkableFloor>& floor) {
  const std::vector<glm::dvec3> cameras = reflectionCameras(level, probe, o, floor);
  const bool floorOnly = set == SampleSet::MirrorFloor;
  std::mt19937 rng(o.seed * 2654435761u + (floorOnly ? 0u : 1u));

  std::vector<ReflectionSample> samples;
  samples.reserve(o.targetSamples);
  const std::size_t batch = 512;
  std::vector<Ray> rays(batch);
  std::vector<RayHit> hits(batch);
  std::size_t attempts = 0;
  const std::size_t maxAttempts =
      o.targetSamples * static_cast<std::size_t>(o.maxAttemptsPerSample);
  while (samples.size() < o.targetSamples && attempts < maxAttempts) {
    // Cameras take turns, so every part of the volume is seen even when the target is small.
    for (std::size_t i = 0; i < batch; ++i) {
      const glm::dvec3 eye = cameras[(attempts + i) % cameras.size()];
      rays[i] = {eye, glm::vec3(floorOnly ? drawPlayerFloorDirection(rng) : uniformDirection(rng))};
    }
    level.firstHits(rays, hits);
    attempts += batch;
    for (std::size_t i = 0; i < batch && samples.size() < o.targetSamples; ++i) {
      if (!hits[i].hit()) continue;
      ReflectionSample s;
      s.eyeMeters = cameras[(attempts - batch + i) % cameras.size()];
      const glm::dvec3 view = glm::normalize(glm::dvec3(rays[i].direction));
      s.xMeters = s.eyeMeters + double(hits[i].t) * view;
      if (!insideInfluence(probe.influence, s.xMeters)) continue;
      s.normal = glm::dvec3(hits[i].geometricNormal);
      if (glm::dot(s.normal, view) > 0) s.normal = -s.normal;  // face the camera
      if (floorOnly && s.normal.z < o.upwardCosine) continue;
      if (floorOnly && !onServedFloor(floor, s.xMeters)) continue;
      s.reflected = glm::normalize(view - 2.0 * glm::dot(view, s.normal) * s.normal);
      samples.push_back(s);
    }
  }
  for (ReflectionSample& s : samples) {
    traceTrueHit(level, s);
    s.occluded = trueHitHiddenFrom(level, probe.captureMeters, s);
  }
  return samples;
}

}  // namespace probeproxy
