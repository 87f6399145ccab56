#include "geometry/export/unit_transform.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace probeproxy {

glm::dmat4 toUnitTransform(glm::dvec3 center, glm::dvec3 halfExtents, const glm::dquat& rotation) {
  const glm::dmat3 shapeFromWorld = glm::transpose(glm::mat3_cast(rotation));
  const glm::dvec3 offset = shapeFromWorld * center;
  glm::dmat4 m(0.0);  // column-major: m[column][row]
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) m[col][row] = shapeFromWorld[col][row] / halfExtents[row];
    m[3][row] = -offset[row] / halfExtents[row];
  }
  m[3][3] = 1.0;
  return m;
}

ConvexProxy icosphereMesh(glm::dvec3 center, glm::dvec3 radii, const glm::dquat& rotation,
                          int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> unit = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                  {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                  {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (glm::dvec3& v : unit) v = glm::normalize(v);
  std::vector<glm::uvec3> triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;  // deterministic order
    const auto midpoint = [&](unsigned a, unsigned b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = midpoints.emplace(key, static_cast<unsigned>(unit.size()));
      if (added) unit.push_back(glm::normalize(unit[a] + unit[b]));
      return it->second;
    };
    std::vector<glm::uvec3> finer;
    for (const glm::uvec3& tri : triangles) {
      const unsigned ab = midpoint(tri.x, tri.y);
      const unsigned bc = midpoint(tri.y, tri.z);
      const unsigned ca = midpoint(tri.z, tri.x);
      finer.emplace_back(tri.x, ab, ca);
      finer.emplace_back(tri.y, bc, ab);
      finer.emplace_back(tri.z, ca, bc);
      finer.emplace_back(ab, bc, ca);
    }
    triangles = std::move(finer);
  }
  ConvexProxy mesh;
  const glm::dmat3 axes = glm::mat3_cast(rotation);
  for (const glm::dvec3& v : unit) mesh.verticesMeters.push_back(center + axes * (v * radii));
  mesh.triangles = std::move(triangles);
  return mesh;
}

}  // namespace probeproxy
