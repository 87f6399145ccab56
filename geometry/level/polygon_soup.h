#pragma once
// A mesh file's polygons as read, before they become the level's triangles: points in the
// file's units and frame, faces as runs of vertex indices (flat, so a file of many small faces
// costs two vectors, not one per face).

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace probeproxy {

struct PolygonSoup {
  std::vector<glm::dvec3> points;
  std::vector<std::size_t> corners;   // every face's vertex indices, face after face
  std::vector<std::size_t> faceEnds;  // one past each face's last corner in `corners`
};

}  // namespace probeproxy
