#include "core/mixing/mixing_plane.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace probeproxy {

namespace {

bool isFinite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

RayChord rayChord(const std::vector<ProxyPlane>& planes, glm::dvec3 origin, glm::dvec3 direction) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  RayChord chord{-inf, inf};
  for (const ProxyPlane& p : planes) {
    const double towards = glm::dot(p.normal, direction);
    const double gap = p.offsetMeters - glm::dot(p.normal, origin);  // >= 0 on the inner side
    if (towards > 0) {
      chord.exit = std::min(chord.exit, gap / towards);
    } else if (towards < 0) {
      chord.enter = std::max(chord.enter, gap / towards);
    } else if (gap < 0) {
      // Parallel and outside: the line never gets in (no 0/0 or inf/inf on the way).
      return {inf, -inf};
    }
  }
  return chord;
}

bool rayExitsProxy(const RayChord& chord, double minExit) {
  return std::isfinite(chord.exit) && chord.exit > chord.enter && chord.exit > minExit;
}

LookupCube mixingPlaneLookups(const ConvexProxy& proxy, glm::dvec3 capture,
                              glm::dvec3 reflectedCamera, int faceSize) {
  if (proxy.planes.empty()) throw std::invalid_argument("mixing_plane: the proxy has no planes");
  if (!isFinite(capture) || !isFinite(reflectedCamera))
    throw std::invalid_argument("mixing_plane: capture point and camera must be finite");
  // Exits closer to E' than rounding of its coordinates can tell from E' itself are misses:
  // E' on the boundary, looking out.
  const glm::dvec3 e = glm::abs(reflectedCamera);
  const double minExitMeters = 1e-9 * (1.0 + std::max(e.x, std::max(e.y, e.z)));
  LookupCube cube = emptyLookupCube(faceSize);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < faceSize; ++row) {
      for (int col = 0; col < faceSize; ++col) {
        const glm::dvec3 d = texelRayDirection(static_cast<CubeFace>(f), col, row, faceSize);
        const RayChord chord = rayChord(proxy.planes, reflectedCamera, d);
        if (!rayExitsProxy(chord, minExitMeters / glm::length(d))) continue;
        const glm::dvec3 lookup = reflectedCamera + chord.exit * d - capture;
        if (lookup == glm::dvec3(0.0) || !isFinite(lookup)) continue;
        const std::size_t i = static_cast<std::size_t>(row) * faceSize + col;
        cube.lookupMeters[f][i] = lookup;
        cube.miss[f][i] = 0;
      }
    }
  }
  return cube;
}

}  // namespace probeproxy
