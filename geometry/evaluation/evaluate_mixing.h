#pragma once
// The angular error of the mixing step (core/mixing/) over a probe's reflection samples on its
// reflection plane. For a sample x seen from camera e, the mixing step answers from the cube it
// corrected for the reflected camera e': the texel that holds direction r (nearest texel, the
// cube's resolution), whose lookup vector is P - C with P where the ray from e' through that
// texel leaves the proxy. Its error is angle(P - C, H - C), H the true hit, as for per-pixel
// methods (evaluate_shape.h); a missed texel is a miss.

#include "core/measures/error_figures.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/proxy/convex_proxy.h"
#include "core/scene/probe.h"
#include "geometry/evaluation/reflection_sample.h"

#include <span>
#include <vector>

namespace probeproxy {

// The samples that lie on `plane` (within 1 mm) with its normal: the mirror the step corrects.
std::vector<ReflectionSample> samplesOnPlane(std::span<const ReflectionSample> samples,
                                             const ReflectionPlane& plane);

// One lookup cube of `faceSize` per distinct camera of `samples` (built in parallel); samples
// off the plane are left out (samplesOnPlane). Throws what mixingLookups throws.
ErrorFigures evaluateMixing(MixingMethod method, const ConvexProxy& proxy, glm::dvec3 captureMeters,
                            const ReflectionPlane& plane, std::span<const ReflectionSample> samples,
                            int faceSize);

// The texel of a `faceSize` cube whose area holds `direction`: face and row * faceSize + col.
struct CubeTexel {
  CubeFace face = CubeFace::px;
  std::size_t index = 0;
};
CubeTexel nearestCubeTexel(glm::dvec3 direction, int faceSize);

}  // namespace probeproxy
