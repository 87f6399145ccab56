#include "geometry/probe_proxies/authored_proxy_shape.h"

#include "geometry/fit/fan_apex.h"
#include "geometry/level/load_level.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace probeproxy {

namespace {

// validate's proxy_degenerate_face: a triangle lower than this times the mesh's size.
constexpr double kSliverHeightRelative = 1e-6;

}  // namespace

ConvexProxy convexFromMesh(std::vector<glm::dvec3> vertices, std::vector<glm::uvec3> triangles) {
  // The planes depend on the triangles as points only, not on how a file orders its vertices
  // and faces (a mesh read back through Assimp comes in another order, and a plane taken from
  // another of a face's triangles differs in its last bits): each triangle starts at its least
  // corner, winding kept, and the triangles are taken in the order of their corners.
  using Corners = std::array<glm::dvec3, 3>;
  const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  };
  std::vector<Corners> faces;
  faces.reserve(triangles.size());
  glm::dvec3 lo(0.0), hi(0.0);
  if (!vertices.empty()) lo = hi = vertices.front();
  for (const glm::dvec3& v : vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  for (const glm::uvec3& t : triangles) {
    Corners c{vertices[t.x], vertices[t.y], vertices[t.z]};
    const std::size_t first =
        less(c[1], c[0]) ? (less(c[2], c[1]) ? 2 : 1) : (less(c[2], c[0]) ? 2 : 0);
    std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(first), c.end());
    faces.push_back(c);
  }
  std::sort(faces.begin(), faces.end(), [&](const Corners& a, const Corners& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
  });
  ConvexProxy convex;
  const double offsetTolerance = 1e-6 * std::max(glm::length(hi - lo), 1.0);
  // A sliver's plane is its corners' rounding, pointing anywhere: one cut dieselpower's
  // written layout proxy through its capture point, and the survey measured that cut. Its edges
  // belong to wider triangles, whose planes bound the proxy; validate's proxy_degenerate_face
  // (the same 1e-6 of the size) names it.
  const double sliverHeight = kSliverHeightRelative * glm::length(hi - lo);
  for (const Corners& c : faces) {
    const glm::dvec3 n = glm::cross(c[1] - c[0], c[2] - c[0]);
    if (glm::length(n) == 0.0 || !(smallestHeight(c[0], c[1], c[2]) > sliverHeight)) continue;
    const ProxyPlane plane{glm::normalize(n), glm::dot(glm::normalize(n), c[0])};
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
  if (const auto* cheapK = std::get_if<AuthoredCheapK>(&spec))
    return CheapKShape{cheapK->kPerMeter};
  const LevelMesh loaded = loadAuthoredProxyMesh(std::get<AuthoredConvexMesh>(spec), scene);
  std::vector<glm::dvec3> vertices(loaded.positionsMeters.begin(), loaded.positionsMeters.end());
  return convexFromMesh(std::move(vertices), loaded.triangles);
}

bool sceneFileCanHold(const ProxyShape& shape) {
  if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    const glm::dvec3 r = sphere->radiiMeters;
    return r.x == r.y && r.y == r.z;
  }
  return true;
}

bool layoutChoosesAmong(const ProxyShape& shape) {
  return sceneFileCanHold(shape) && !std::holds_alternative<CheapKShape>(shape);
}

}  // namespace probeproxy
