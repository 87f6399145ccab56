#include "geometry/evaluation/evaluate_mixing.h"

#include "core/cube/cube_face.h"
#include "core/mixing/reflected_camera.h"
#include "geometry/evaluation/evaluate_shape.h"

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace probeproxy {

CubeTexel nearestCubeTexel(glm::dvec3 direction, int faceSize) {
  const FaceUv fuv = faceUvFromDirection(glm::vec3(direction));
  const int col = std::clamp(static_cast<int>(fuv.uv.x * float(faceSize)), 0, faceSize - 1);
  const int row = std::clamp(static_cast<int>(fuv.uv.y * float(faceSize)), 0, faceSize - 1);
  return {fuv.face, static_cast<std::size_t>(row) * static_cast<std::size_t>(faceSize) +
                        static_cast<std::size_t>(col)};
}

std::vector<ReflectionSample> samplesOnPlane(std::span<const ReflectionSample> samples,
                                             const ReflectionPlane& plane) {
  const glm::dvec3 n = glm::normalize(plane.normal);
  std::vector<ReflectionSample> on;
  for (const ReflectionSample& s : samples) {
    if (std::abs(heightAbovePlaneMeters(s.xMeters, plane)) <= 1e-3 &&
        glm::dot(s.normal, n) > 0.9999)
      on.push_back(s);
  }
  return on;
}

ErrorFigures evaluateMixing(MixingMethod method, const ConvexProxy& proxy, glm::dvec3 captureMeters,
                            const ReflectionPlane& plane, std::span<const ReflectionSample> samples,
                            int faceSize) {
  const std::vector<ReflectionSample> on = samplesOnPlane(samples, plane);
  // The samples of each camera: one corrected cube serves them all.
  const auto eyeKey = [](glm::dvec3 e) { return std::make_tuple(e.x, e.y, e.z); };
  std::map<std::tuple<double, double, double>, std::vector<std::size_t>> byEye;
  std::size_t occluded = 0;
  for (std::size_t i = 0; i < on.size(); ++i) {
    if (on[i].occluded)
      ++occluded;
    else
      byEye[eyeKey(on[i].eyeMeters)].push_back(i);
  }
  std::vector<std::vector<std::size_t>> groups;
  for (auto& [eye, indices] : byEye) groups.push_back(std::move(indices));

  std::vector<double> errors(on.size(), std::nan(""));
  tbb::parallel_for(std::size_t(0), groups.size(), [&](std::size_t g) {
    const glm::dvec3 eye = on[groups[g].front()].eyeMeters;
    const LookupCube cube =
        mixingLookups(method, proxy, captureMeters, reflectThroughPlane(eye, plane), faceSize);
    for (std::size_t i : groups[g]) {
      const ReflectionSample& s = on[i];
      const CubeTexel t = nearestCubeTexel(s.reflected, faceSize);
      const auto face = static_cast<std::size_t>(t.face);
      if (cube.miss[face][t.index]) continue;  // NaN: a miss
      const glm::dvec3 ideal = s.hitsSky ? s.reflected : s.trueHitMeters - captureMeters;
      errors[i] = angleBetweenDeg(cube.lookupMeters[face][t.index], ideal);
    }
  });
  std::vector<double> visible;
  for (std::size_t i = 0; i < on.size(); ++i)
    if (!on[i].occluded) visible.push_back(errors[i]);
  return summarizeErrors(std::move(visible), occluded);
}

}  // namespace probeproxy
