#include "core/mixing/corrected_cubemap.h"

#include "core/cube/cubemap_sampling.h"
#include "core/mixing/mixing_plane.h"
#include "core/mixing/raster_convex.h"

#include <stdexcept>

namespace probeproxy {

std::string_view mixingMethodName(MixingMethod method) {
  return method == MixingMethod::MixingPlane ? "mixing_plane" : "raster_convex";
}

std::optional<MixingMethod> mixingMethodFromName(std::string_view name) {
  if (name == "mixing_plane") return MixingMethod::MixingPlane;
  if (name == "raster_convex") return MixingMethod::RasterConvex;
  return std::nullopt;
}

LookupCube mixingLookups(MixingMethod method, const ConvexProxy& proxy, glm::dvec3 capture,
                         glm::dvec3 reflectedCamera, int faceSize) {
  return method == MixingMethod::MixingPlane
             ? mixingPlaneLookups(proxy, capture, reflectedCamera, faceSize)
             : rasterConvexLookups(proxy, capture, reflectedCamera, faceSize);
}

CorrectedCubemap correctCubemap(const Cubemap& source, glm::dvec3 capture, const ConvexProxy& proxy,
                                glm::dvec3 reflectedCamera, MixingMethod method) {
  if (source.numLevels() == 0) throw std::invalid_argument("correctCubemap: empty source cubemap");
  CorrectedCubemap out;
  for (int level = 0; level < source.numLevels(); ++level) {
    const int n = source.faceSize(level);
    const LookupCube lookups = mixingLookups(method, proxy, capture, reflectedCamera, n);
    CubemapLevel corrected;
    corrected.faceSize = n;
    for (int f = 0; f < kCubeFaceCount; ++f) {
      std::vector<float>& rgb = corrected.rgb[f];
      rgb.resize(static_cast<std::size_t>(n) * n * 3);
      for (std::size_t i = 0; i < lookups.miss[f].size(); ++i) {
        const glm::vec3 colour = lookups.miss[f][i]
                                     ? glm::vec3(kMissRgb[0], kMissRgb[1], kMissRgb[2])
                                     : sampleBilinear(source, glm::vec3(lookups.lookupMeters[f][i]),
                                                      static_cast<float>(level));
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = colour[c];
      }
    }
    out.cube.levels.push_back(std::move(corrected));
    out.missMask.push_back(lookups.miss);
  }
  return out;
}

std::size_t missCount(const CorrectedCubemap& corrected) {
  std::size_t count = 0;
  for (const auto& level : corrected.missMask)
    for (const auto& face : level)
      for (std::uint8_t m : face) count += m;
  return count;
}

}  // namespace probeproxy
