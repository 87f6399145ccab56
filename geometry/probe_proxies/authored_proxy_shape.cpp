#include "geometry/probe_proxies/authored_proxy_shape.h"

#include "geometry/level/load_level.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

ConvexProxy convexFromMesh(std::vector<glm::dvec3> vertices, std::vector<glm::uvec3> triangles) {
  ConvexProxy convex;
  double size = 0.0;
  for (const glm::dvec3& v : vertices) size = std::max(size, glm::length(v - vertices.front()));
  const double offsetTolerance = 1e-6 * std::max(size, 1.0);
  for (const glm::uvec3& t : triangles) {
    const glm::dvec3 n = glm::cross(vertices[t.y] - vertices[t.x], vertices[t.z] - vertices[t.x]);
    if (glm::length(n) == 0.0) continue;
    const ProxyPlane plane{glm::normalize(n), glm::dot(glm::normalize(n), vertices[t.x])};
    const bool known =
        std::any_of(convex.planes.begin(), convex.planes.end(), [&](const ProxyPlane& p) {
          return glm::dot(p.normal, plane.normal) > 1.0 - 1e-9 &&
                 std::abs(p.offsetMeters - plane.offsetMeters) < offsetTolerance;
        });
    if (!known) convex.planes.push_back(plane);
  }
  convex.verticesMeters = std::move(vertices);
  convex.triangles = std::move(triangles);
  return convex;
}

LevelMesh loadAuthoredProxyMesh(const AuthoredConvexMesh& mesh, const Scene& scene) {
  // glTF is Y-up by its specification; other formats are in the scene file's frame.
  const std::string ext = mesh.mesh.extension().string();
  const UpAxis up = (ext == ".glb" || ext == ".gltf") ? UpAxis::Y : scene.fileUp;
  return loadLevelMeshFile(mesh.mesh, up, scene.metersPerUnit);
}

std::optional<ProxyShape> authoredProxyShape(const ProxySpec& spec, const Scene& scene) {
  if (std::holds_alternative<AutoProxy>(spec)) return std::nullopt;
  if (std::holds_alternative<InfiniteProxy>(spec)) return InfiniteShape{};
  if (const auto* box = std::get_if<AuthoredBox>(&spec)) {
    return BoxShape{box->centerMeters, box->halfExtentsMeters, glm::dquat(1, 0, 0, 0)};
  }
  if (const auto* obb = std::get_if<AuthoredObb>(&spec)) {
    return BoxShape{obb->centerMeters, obb->halfExtentsMeters, obb->worldFromBox};
  }
  if (const auto* sphere = std::get_if<AuthoredSphere>(&spec)) {
    return SphereShape{sphere->centerMeters, glm::dvec3(sphere->radiusMeters),
                       glm::dquat(1, 0, 0, 0)};
  }
  const LevelMesh loaded = loadAuthoredProxyMesh(std::get<AuthoredConvexMesh>(spec), scene);
  std::vector<glm::dvec3> vertices(loaded.positionsMeters.begin(), loaded.positionsMeters.end());
  return convexFromMesh(std::move(vertices), loaded.triangles);
}

bool sceneFileCanHold(const ProxyShape& shape) {
  if (std::holds_alternative<CheapKShape>(shape)) return false;
  if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    const glm::dvec3 r = sphere->radiiMeters;
    return r.x == r.y && r.y == r.z;
  }
  return true;
}

}  // namespace probeproxy
