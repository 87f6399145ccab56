#include "core/proxy/proxy_shape.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy {

double signedDistanceOutside(const std::vector<ProxyPlane>& planes, glm::dvec3 x) {
  double outside = -std::numeric_limits<double>::infinity();
  for (const ProxyPlane& p : planes)
    outside = std::max(outside, glm::dot(p.normal, x) - p.offsetMeters);
  return outside;
}

std::vector<double> planeAreasSquareMeters(const ConvexProxy& proxy) {
  std::vector<double> areas(proxy.planes.size(), 0.0);
  if (proxy.planes.empty()) return areas;
  for (const glm::uvec3& t : proxy.triangles) {
    const glm::dvec3 a = proxy.verticesMeters[t.x], b = proxy.verticesMeters[t.y],
                     c = proxy.verticesMeters[t.z];
    const glm::dvec3 centroid = (a + b + c) / 3.0;
    std::size_t on = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < proxy.planes.size(); ++i) {
      const double d =
          std::abs(glm::dot(proxy.planes[i].normal, centroid) - proxy.planes[i].offsetMeters);
      if (d < nearest) nearest = d, on = i;
    }
    areas[on] += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return areas;
}

glm::dvec3 reachDirection(int i, int directions) {
  const double z = 1.0 - 2.0 * (i + 0.5) / directions;
  const double phi = i * 2.399963229728653;  // the golden angle
  const double s = std::sqrt(1.0 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

double planeExitMeters(const ProxyPlane& p, glm::dvec3 from, glm::dvec3 v) {
  const double towards = glm::dot(p.normal, v);
  return towards > 0 ? (p.offsetMeters - glm::dot(p.normal, from)) / towards
                     : std::numeric_limits<double>::infinity();
}

double farthestExitMeters(const std::vector<ProxyPlane>& planes, glm::dvec3 from, int directions) {
  double farthest = 0.0;
  for (int i = 0; i < directions; ++i) {
    const glm::dvec3 v = reachDirection(i, directions);
    double exit = std::numeric_limits<double>::infinity();
    for (const ProxyPlane& p : planes) exit = std::min(exit, planeExitMeters(p, from, v));
    farthest = std::max(farthest, exit);
  }
  return farthest;
}

double farthestCornerMeters(const ConvexProxy& proxy, glm::dvec3 from) {
  double farthest = 0.0;
  for (const glm::dvec3& v : proxy.verticesMeters)
    farthest = std::max(farthest, glm::length(v - from));
  return farthest;
}

Method methodOf(const ProxyShape& shape) {
  struct Visitor {
    Method operator()(const InfiniteShape&) const { return Method::Infinite; }
    Method operator()(const CheapKShape&) const { return Method::CheapK; }
    Method operator()(const SphereShape&) const { return Method::Sphere; }
    Method operator()(const BoxShape& b) const {
      return b.worldFromBox == glm::dquat(1, 0, 0, 0) ? Method::Aabb : Method::Obb;
    }
    Method operator()(const ConvexProxy&) const { return Method::Convex; }
  };
  return std::visit(Visitor{}, shape);
}

std::string_view methodName(Method method) {
  switch (method) {
    case Method::Infinite:
      return "infinite";
    case Method::CheapK:
      return "cheap_k";
    case Method::Sphere:
      return "sphere";
    case Method::Aabb:
      return "aabb";
    case Method::Obb:
      return "obb";
    case Method::Convex:
      return "convex";
  }
  return "unknown";
}

std::optional<Method> methodFromName(std::string_view name) {
  for (Method m : {Method::Infinite, Method::CheapK, Method::Sphere, Method::Aabb, Method::Obb,
                   Method::Convex}) {
    if (methodName(m) == name) return m;
  }
  return std::nullopt;
}

std::string_view methodId(const ProxyShape& shape) { return methodName(methodOf(shape)); }

int planeCount(const ProxyShape& shape) {
  if (std::holds_alternative<BoxShape>(shape)) return 6;
  if (const auto* convex = std::get_if<ConvexProxy>(&shape))
    return static_cast<int>(convex->planes.size());
  return 0;
}

bool holdsVolume(const ProxyShape& shape) {
  const auto thick = [](glm::dvec3 half) {
    return std::isfinite(half.x) && std::isfinite(half.y) && std::isfinite(half.z) &&
           std::min({half.x, half.y, half.z}) >= kThinnestShapeMeters;
  };
  if (const auto* box = std::get_if<BoxShape>(&shape)) return thick(box->halfExtentsMeters);
  if (const auto* sphere = std::get_if<SphereShape>(&shape)) return thick(sphere->radiiMeters);
  return true;
}

bool strictlyContains(const ProxyShape& shape, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxShape>(&shape))
    return signedDistanceOutside(convexFromBox(*box).planes, p) < 0;
  if (const auto* convex = std::get_if<ConvexProxy>(&shape))
    return signedDistanceOutside(convex->planes, p) < 0;
  if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    const glm::dvec3 local =
        (glm::conjugate(sphere->worldFromSphere) * (p - sphere->centerMeters)) /
        sphere->radiiMeters;
    return glm::dot(local, local) < 1.0;
  }
  return true;
}

ConvexProxy convexFromBox(const BoxShape& box) {
  ConvexProxy convex;
  const glm::dmat3 axes = glm::mat3_cast(box.worldFromBox);
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      const glm::dvec3 n = sign * axes[axis];
      convex.planes.push_back({n, glm::dot(n, box.centerMeters) + box.halfExtentsMeters[axis]});
    }
  }
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 local((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    convex.verticesMeters.push_back(box.centerMeters + axes * (local * box.halfExtentsMeters));
  }
  // Corner i has bit 0 = +x, bit 1 = +y, bit 2 = +z; quads counter-clockwise from outside.
  const unsigned quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  for (const auto& q : quads) {
    convex.triangles.emplace_back(q[0], q[1], q[2]);
    convex.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return convex;
}

}  // namespace probeproxy
