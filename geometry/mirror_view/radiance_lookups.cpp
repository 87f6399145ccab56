#include "geometry/mirror_view/radiance_lookups.h"

#include "core/cube/cubemap_sampling.h"
#include "core/parallax/prepared_proxy.h"
#include "geometry/evaluation/evaluate_mixing.h"

namespace probeproxy {

RadianceLookup proxyRadianceLookup(const Cubemap& cube, const ProxyShape& shape,
                                   glm::dvec3 captureMeters) {
  return [&cube, proxy = prepareProxy(shape, captureMeters)](
             glm::dvec3 x, glm::dvec3 r) -> std::optional<glm::vec3> {
    const seed::Lookup d = lookupScalar(proxy, glm::vec3(x), glm::vec3(r));
    if (d.miss) return std::nullopt;
    return sampleBilinear(cube, d.direction, 0.0f);
  };
}

RadianceLookup trueHitRadianceLookup(const Cubemap& cube, const LevelRayCaster& level,
                                     glm::dvec3 captureMeters) {
  return [&cube, &level, captureMeters](glm::dvec3 x, glm::dvec3 r) -> std::optional<glm::vec3> {
    Ray ray;
    ray.originMeters = x;
    ray.direction = glm::vec3(r);
    // Leave the mirror plane the ray starts on.
    ray.tMin = 1e-5f;
    const RayHit hit = level.firstHit(ray);
    if (!hit.hit()) return sampleBilinear(cube, glm::vec3(r), 0.0f);
    const glm::dvec3 h = x + static_cast<double>(hit.t) * r;
    return sampleBilinear(cube, glm::vec3(h - captureMeters), 0.0f);
  };
}

RadianceLookup correctedCubeRadianceLookup(const CorrectedCubemap& corrected) {
  return [&corrected](glm::dvec3, glm::dvec3 r) -> std::optional<glm::vec3> {
    const CubeTexel t = nearestCubeTexel(r, corrected.cube.faceSize(0));
    if (corrected.missMask.at(0)[static_cast<std::size_t>(t.face)][t.index]) return std::nullopt;
    return sampleBilinear(corrected.cube, glm::vec3(r), 0.0f);
  };
}

RadianceLookup pointCloudRadianceLookup(const PointCloud& cloud, const PointCloudOptions& options) {
  return [&cloud, options](glm::dvec3 x, glm::dvec3 r) {
    return pointCloudRadiance(cloud, x, glm::vec3(r), options);
  };
}

}  // namespace probeproxy
