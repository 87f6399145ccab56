#include "core/mixing/glossy_distortion.h"

#include "core/mixing/mixing_plane.h"
#include "core/mixing/reflected_camera.h"
#include "core/parallax/reference_lookup.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace probeproxy {

namespace {

// A uniform number in (0, 1) from the generator's 32 bits, the same on every standard library
// (std::uniform_real_distribution is not).
double unitUniform(std::mt19937& rng) { return (static_cast<double>(rng()) + 0.5) / 4294967296.0; }

double angleDegrees(glm::dvec3 a, glm::dvec3 b) {
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

struct Basis {
  glm::dvec3 t, b, n;
};

Basis planeBasis(glm::dvec3 n) {
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(helper, n));
  return {t, glm::cross(n, t), n};
}

struct ShadingPoint {
  glm::dvec3 xMeters;
  double u1, u2;  // the GGX lobe's random numbers
};

}  // namespace

std::vector<GlossyDistortion> glossyDistortion(const GlossySetup& setup,
                                               const std::vector<double>& roughnesses) {
  if (setup.pixels < 1) throw std::invalid_argument("glossyDistortion: pixels must be >= 1");
  for (double r : roughnesses)
    if (!(r >= 0.0 && r <= 1.0))
      throw std::invalid_argument("glossyDistortion: roughness must lie in [0, 1]");
  const double height = heightAbovePlaneMeters(setup.cameraMeters, setup.plane);
  if (!(height > 0.0))
    throw std::invalid_argument("glossyDistortion: the camera must be above the plane");
  const Basis basis = planeBasis(glm::normalize(setup.plane.normal));
  const glm::dvec3 foot = setup.cameraMeters - height * basis.n;
  const glm::dvec3 reflected = reflectThroughPlane(setup.cameraMeters, setup.plane);

  // The shading points and lobe numbers, drawn once.
  std::mt19937 rng(setup.seed);
  std::vector<ShadingPoint> points;
  for (int attempt = 0;
       attempt < 64 * setup.pixels && static_cast<int>(points.size()) < setup.pixels; ++attempt) {
    const double s = (2.0 * unitUniform(rng) - 1.0) * setup.receiverHalfSizeMeters;
    const double t = (2.0 * unitUniform(rng) - 1.0) * setup.receiverHalfSizeMeters;
    const double u1 = unitUniform(rng), u2 = unitUniform(rng);
    const glm::dvec3 x = foot + s * basis.t + t * basis.b;
    if (signedDistanceOutside(setup.proxy.planes, x) > 1e-6) continue;
    points.push_back({x, u1, u2});
  }
  if (points.empty())
    throw std::invalid_argument(
        "glossyDistortion: no shading point on the plane lies in the proxy");

  const ProxyShape shape = setup.proxy;
  std::vector<GlossyDistortion> results;
  for (double roughness : roughnesses) {
    GlossyDistortion result;
    result.roughness = roughness;
    const double alpha = roughness * roughness;
    for (const ShadingPoint& p : points) {
      const double thetaM = std::atan(alpha * std::sqrt(p.u1 / (1.0 - p.u1)));
      const double phi = 2.0 * glm::pi<double>() * p.u2;
      const glm::dvec3 m = std::sin(thetaM) * (std::cos(phi) * basis.t + std::sin(phi) * basis.b) +
                           std::cos(thetaM) * basis.n;
      const glm::dvec3 r = glm::reflect(glm::normalize(p.xMeters - setup.cameraMeters), m);
      const RayChord fromReflected = rayChord(setup.proxy.planes, reflected, r);
      const bool mixingHits = rayExitsProxy(fromReflected);
      if (!(glm::dot(r, basis.n) > 0.0)) {
        ++result.belowPlane;
        if (!mixingHits) ++result.mixingMissesBelowPlane;
        continue;
      }
      const auto perPixel = referenceLookup(shape, setup.captureMeters, p.xMeters, r);
      if (!mixingHits || !perPixel) {
        result.errorsDeg.push_back(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      const glm::dvec3 mixing = reflected + fromReflected.exit * r - setup.captureMeters;
      result.errorsDeg.push_back(angleDegrees(mixing, *perPixel));
    }
    result.figures = summarizeErrors(result.errorsDeg, 0);
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace probeproxy
