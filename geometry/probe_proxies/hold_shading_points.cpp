#include "geometry/probe_proxies/hold_shading_points.h"

#include "core/errors/invariant_checks.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace probeproxy {

BoxShape holdingShadingPoints(BoxShape box, std::span<const ReflectionSample> samples) {
  PROBEPROXY_CHECK(box.worldFromBox == glm::dquat(1, 0, 0, 0));
  glm::dvec3 lo = box.centerMeters - box.halfExtentsMeters;
  glm::dvec3 hi = box.centerMeters + box.halfExtentsMeters;
  for (const ReflectionSample& s : samples)
    if (!s.occluded) lo = glm::min(lo, s.xMeters), hi = glm::max(hi, s.xMeters);
  return BoxShape{0.5 * (lo + hi), 0.5 * (hi - lo)};
}

std::vector<ProxyPlane> holdingShadingPoints(std::vector<ProxyPlane> planes,
                                             std::span<const ReflectionSample> samples) {
  for (ProxyPlane& p : planes)
    for (const ReflectionSample& s : samples)
      if (!s.occluded) p.offsetMeters = std::max(p.offsetMeters, glm::dot(p.normal, s.xMeters));
  return planes;
}

}  // namespace probeproxy
