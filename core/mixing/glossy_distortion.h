#pragma once
// The glossy analysis of Lagarde & Zanuttini's bonus slides: the mixing step assumes a flat mirror,
// so the cube corrected from the reflected camera E' is right only for receiver normals equal to
// the plane's. A glossy receiver perturbs its normal; the shader then looks the corrected cube up
// along the perturbed reflection r, which from E' reaches a different proxy point than the ray
// (x, r) from the shading point does. This measures that distortion against per-pixel
// correction, and how often the mixing step misses (the seed's red texels).

#include "core/measures/error_figures.h"
#include "core/proxy/convex_proxy.h"
#include "core/scene/probe.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace probeproxy {

struct GlossySetup {
  ConvexProxy proxy;  // the probe's proxy; an exact one isolates the flat-mirror assumption
  glm::dvec3 captureMeters{0.0};
  glm::dvec3 cameraMeters{0.0};
  ReflectionPlane plane;  // the receiver, e.g. the floor
  // Shading points x: uniform on the plane in a square of this half-size around the camera's
  // foot, kept where they lie in the proxy (on its boundary within 1e-6 m).
  double receiverHalfSizeMeters = 3.0;
  int pixels = 4096;       // shading points per roughness
  std::uint32_t seed = 1;  // std::mt19937; the same points and normals for every roughness
};

struct GlossyDistortion {
  double roughness = 0.0;  // perceptual; the GGX lobe's alpha = roughness^2
  // Per shading point whose perturbed reflection r leaves the plane (dot(r, n) > 0): the angle
  // in degrees between the mixing step's lookup (where the ray (E', r) leaves the proxy, minus
  // C) and per-pixel correction's (where (x, r) leaves it, minus C). NaN where the mixing step
  // misses: summarizeErrors counts those as misses.
  std::vector<double> errorsDeg;
  ErrorFigures figures;  // summarizeErrors(errorsDeg, 0)
  // Perturbed reflections into the plane (dot(r, n) <= 0), which a shader masks: left out of
  // errorsDeg; mixingMissesBelowPlane of them miss the proxy from E' as well.
  std::size_t belowPlane = 0;
  std::size_t mixingMissesBelowPlane = 0;
};

// One entry per roughness (in [0, 1]), in the given order. The microfacet normal m is drawn
// from the GGX distribution around the plane normal (alpha = roughness^2, theta_m =
// atan(alpha sqrt(u / (1 - u))), phi uniform) with the same random numbers for every
// roughness, so the curves are smooth; r = reflect(x - E, m). Deterministic for a seed. Throws
// std::invalid_argument when the camera is not above the plane, a roughness is outside
// [0, 1], pixels < 1, or no shading point lands in the proxy.
std::vector<GlossyDistortion> glossyDistortion(const GlossySetup& setup,
                                               const std::vector<double>& roughnesses);

}  // namespace probeproxy
