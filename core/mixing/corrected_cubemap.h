#pragma once
// The mixing step's output (Lagarde & Zanuttini 2012): a probe's cubemap parallax-corrected for one
// camera and one reflection plane, as a cubemap centred at the reflected camera E'. Every mip level
// is corrected on its own (output level l looks up source level l), as the seed does for a
// prefiltered chain, so glossy receivers keep their blur.

#include "core/cube/cubemap.h"
#include "core/mixing/lookup_cube.h"
#include "core/proxy/convex_proxy.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace probeproxy {

enum class MixingMethod { MixingPlane, RasterConvex };

// docs/methods_and_measures.md's ids: "mixing_plane", "raster_convex".
std::string_view mixingMethodName(MixingMethod method);
std::optional<MixingMethod> mixingMethodFromName(std::string_view name);

// Linear RGB written where a texel misses the proxy: the seeds' red.
inline constexpr float kMissRgb[3] = {1.0f, 0.0f, 0.0f};

struct CorrectedCubemap {
  // Same level count and face sizes as the source. A missed texel is kMissRgb.
  Cubemap cube;
  // missMask[level][face][row * faceSize + col] = 1 where the texel's ray has no exit.
  std::vector<std::array<std::vector<std::uint8_t>, kCubeFaceCount>> missMask;
};

// The lookup cube of one method.
LookupCube mixingLookups(MixingMethod method, const ConvexProxy& proxy, glm::dvec3 captureMeters,
                         glm::dvec3 reflectedCameraMeters, int faceSize);

// Every level of `source` (captured at `captureMeters`) corrected with `method` for a camera
// whose reflection through the plane is `reflectedCameraMeters`. Each texel samples the source
// seam-aware bilinearly (cubemap_sampling.h) at its level. Throws std::invalid_argument for an
// empty source, and what the method throws.
CorrectedCubemap correctCubemap(const Cubemap& source, glm::dvec3 captureMeters,
                                const ConvexProxy& proxy, glm::dvec3 reflectedCameraMeters,
                                MixingMethod method);

// Missed texels over all levels and faces.
std::size_t missCount(const CorrectedCubemap& corrected);

}  // namespace probeproxy
