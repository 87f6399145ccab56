#include "geometry/layout/capture_sight.h"

#include "geometry/evaluation/reflection_samples.h"
#include "geometry/raycast/capture_depth_cube.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy {

namespace {

enum class Sight { Seen, Hidden, Unsure };

// The nearest and farthest depth of the 3x3 texels around a direction; a face's edge texel is
// unsure (its neighbours lie on another face).
Sight lookUp(const DepthCube& cube, glm::dvec3 direction, double distanceMeters) {
  const FaceUv at = faceUvFromDirection(glm::vec3(direction));
  const int n = cube.faceSize;
  const int col = std::clamp(static_cast<int>(at.uv.x * n), 0, n - 1);
  const int row = std::clamp(static_cast<int>(at.uv.y * n), 0, n - 1);
  if (col == 0 || row == 0 || col == n - 1 || row == n - 1) return Sight::Unsure;
  float nearest = std::numeric_limits<float>::infinity(), farthest = 0.0f;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc) {
      const float d = cube.at(at.face, col + dc, row + dr);
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
  // The sky is seen where every texel around r misses the level, hidden where every one hits.
  if (std::isinf(distanceMeters)) {
    if (std::isinf(nearest)) return Sight::Seen;
    return std::isinf(farthest) ? Sight::Unsure : Sight::Hidden;
  }
  // The true hit lies on a surface: seen when every texel around it reaches it (with slack
  // for the surface's own tilt), hidden when every texel stops well short of it.
  const double slack = 0.02 * distanceMeters + 0.05;
  if (distanceMeters <= double(nearest) - slack) return Sight::Seen;
  if (distanceMeters >= double(farthest) + slack) return Sight::Hidden;
  return Sight::Unsure;
}

}  // namespace

CaptureSight captureSight(const LevelRayCaster& level, glm::dvec3 capture,
                          std::span<const FloorSample> samples, double maxDistanceMeters) {
  const DepthCube cube = captureDepthCube(level, capture, kSightFaceSize);
  const double far2 = maxDistanceMeters > 0.0 ? maxDistanceMeters * maxDistanceMeters
                                              : std::numeric_limits<double>::infinity();
  constexpr double kSkyMeters = std::numeric_limits<double>::infinity();
  CaptureSight sight;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ReflectionSample& s = samples[i].sample;
    const glm::dvec3 toFloor = s.xMeters - capture;
    if (glm::dot(toFloor, toFloor) > far2) continue;
    const glm::dvec3 direction = s.hitsSky ? s.reflected : s.trueHitMeters - capture;
    const double distance = s.hitsSky ? kSkyMeters : glm::length(direction);
    Sight answer = distance < 1e-9 ? Sight::Seen : lookUp(cube, direction, distance);
    if (answer == Sight::Unsure) {
      ++sight.raysCast;
      answer = trueHitHiddenFrom(level, capture, s) ? Sight::Hidden : Sight::Seen;
    }
    if (answer == Sight::Seen) sight.seen.add(static_cast<std::uint32_t>(i));
  }
  compact(sight.seen);
  return sight;
}

}  // namespace probeproxy
