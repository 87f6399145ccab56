#include "geometry/tune/visible_surface_planes.h"

#include "core/cube/cube_face.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

struct PlaneGroup {
  glm::dvec3 normalSum{0.0};  // of unit normals facing away from the capture point
  double offsetSum = 0.0;
  std::size_t texels = 0;
  glm::dvec3 normal() const { return glm::normalize(normalSum); }
  double offset() const { return offsetSum / static_cast<double>(texels); }
};

}  // namespace

std::vector<ProxyPlane> visibleSurfacePlanes(std::span<const RayHit> hits, glm::dvec3 capture,
                                             int faceSize, double offsetTolerance,
                                             double angleToleranceDeg, double minShare,
                                             std::size_t maxPlanes) {
  const double cosTolerance = std::cos(angleToleranceDeg * M_PI / 180.0);
  std::vector<PlaneGroup> groups;
  const std::size_t perFace = static_cast<std::size_t>(faceSize) * faceSize;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].hit()) continue;
    const int face = static_cast<int>(i / perFace);
    const int row = static_cast<int>((i % perFace) / faceSize),
              col = static_cast<int>(i % faceSize);
    const glm::dvec3 point = capture + double(hits[i].t) * glm::dvec3(texelDirection(
                                                               CubeFace(face), col, row, faceSize));
    glm::dvec3 n(hits[i].geometricNormal);
    // The half-space keeps the capture point: its outward normal points away from it.
    if (glm::dot(n, point - capture) < 0) n = -n;
    const double d = glm::dot(n, point);
    // Groups are few (a room has tens of planes): a linear scan, in first-seen order, is
    // deterministic and fast enough.
    auto group = std::find_if(groups.begin(), groups.end(), [&](const PlaneGroup& g) {
      return glm::dot(g.normal(), n) >= cosTolerance && std::abs(g.offset() - d) <= offsetTolerance;
    });
    if (group == groups.end()) group = groups.insert(groups.end(), PlaneGroup{});
    group->normalSum += n;
    group->offsetSum += d;
    ++group->texels;
  }

  std::stable_sort(groups.begin(), groups.end(),
                   [](const PlaneGroup& a, const PlaneGroup& b) { return a.texels > b.texels; });
  std::vector<ProxyPlane> planes;
  const double minTexels = minShare * static_cast<double>(hits.size());
  for (const PlaneGroup& g : groups) {
    if (planes.size() >= maxPlanes || static_cast<double>(g.texels) < minTexels) break;
    const glm::dvec3 n = g.normal();
    // The mean offset of its texels: the wall itself.
    const double d = g.offset();
    if (d - glm::dot(n, capture) <= offsetTolerance) continue;
    planes.push_back({n, d});
  }
  return planes;
}

}  // namespace probeproxy
