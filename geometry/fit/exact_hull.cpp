// One of the three translation units that include CGAL (with oriented_box_fit.cpp and
// bounding_sphere_fit.cpp): everything else in geometry/fit reaches CGAL through exact_hull.h.

#include "geometry/fit/exact_hull.h"

#include "geometry/fit/fit_error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>
#include <unordered_map>

namespace probeproxy::fit {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

Point toCgal(glm::dvec3 p) { return Point(p.x, p.y, p.z); }

// Input points keyed by their bits: the hull's corners are copies of input points, so the
// bits find them back exactly.
struct PointBits {
  std::uint64_t x, y, z;
  bool operator==(const PointBits&) const = default;
};
struct PointBitsHash {
  std::size_t operator()(const PointBits& b) const {
    std::uint64_t h = b.x * 0x9E3779B97F4A7C15ull;
    h ^= (b.y + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
    h ^= (b.z + 0xA4093822299F31D0ull + (h << 6) + (h >> 2));
    return static_cast<std::size_t>(h);
  }
};
PointBits bitsOf(double x, double y, double z) {
  return {std::bit_cast<std::uint64_t>(x), std::bit_cast<std::uint64_t>(y),
          std::bit_cast<std::uint64_t>(z)};
}

}  // namespace

void requireFinite(std::span<const glm::dvec3> points, std::string_view what) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3& p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      std::ostringstream message;
      message << what << ": point " << i << " of " << points.size() << " is not finite (" << p.x
              << ", " << p.y << ", " << p.z << ")";
      throw FitError(message.str());
    }
  }
}

AffineSpan affineSpan(std::span<const glm::dvec3> points) {
  AffineSpan span;
  if (points.empty()) return span;
  span.dimension = 0;
  span.witnesses[0] = 0;
  const Point p0 = toCgal(points[0]);
  std::size_t i = 1;
  // Each search resumes where the previous stopped: every point before it already lies in
  // the span found so far.
  for (; i < points.size(); ++i) {
    if (toCgal(points[i]) != p0) break;
  }
  if (i == points.size()) return span;
  span.dimension = 1;
  span.witnesses[1] = i;
  const Point p1 = toCgal(points[i]);
  for (++i; i < points.size(); ++i) {
    if (!CGAL::collinear(p0, p1, toCgal(points[i]))) break;
  }
  if (i == points.size()) return span;
  span.dimension = 2;
  span.witnesses[2] = i;
  const Point p2 = toCgal(points[i]);
  for (++i; i < points.size(); ++i) {
    if (CGAL::orientation(p0, p1, p2, toCgal(points[i])) != CGAL::COPLANAR) break;
  }
  if (i == points.size()) return span;
  span.dimension = 3;
  span.witnesses[3] = i;
  return span;
}

int orientationSign(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
  // CGAL's orientation is positive when d is on the positive side of the plane through a, b,
  // c, the side from which they turn counter-clockwise: where cross(b - a, c - a) points.
  return static_cast<int>(CGAL::orientation(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

TriangleHull convexHull3(std::span<const glm::dvec3> points, bool withSourceIndex) {
  requireFinite(points, "convex hull");
  std::vector<Point> cgalPoints;
  cgalPoints.reserve(points.size());
  for (const glm::dvec3& p : points) cgalPoints.push_back(toCgal(p));
  // Repeated points reach a use-after-free in CGAL 5.5's quickhull (CGAL issues #6543, #8625:
  // the farthest point can be one of the three it starts from, and is erased twice). Sorted
  // and unique, the input also has one canonical order, whatever order the caller had.
  std::sort(cgalPoints.begin(), cgalPoints.end());
  cgalPoints.erase(std::unique(cgalPoints.begin(), cgalPoints.end()), cgalPoints.end());

  Mesh mesh;
  CGAL::convex_hull_3(cgalPoints.begin(), cgalPoints.end(), mesh);
  // Points that span no volume give a polygon, a segment or a point: callers check the span
  // first, so this is the last guard, not the way to find out.
  if (mesh.number_of_faces() < 4 || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::ostringstream message;
    message << "convex hull: the " << points.size() << " points span no volume";
    throw FitError(message.str());
  }

  // convex_hull_3 builds a fresh mesh, so indices run 0..n-1 with no removed elements. Their
  // order follows heap addresses, though, and changes from call to call: sort corners by
  // position and triangles by corners, so that the same points give the same hull, bit for bit
  // (the facet merging sums areas in this order, the box polish takes the first of equals).
  const std::size_t vertexCount = mesh.number_of_vertices();
  std::vector<glm::dvec3> position(vertexCount);
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    position[v.idx()] = {p.x(), p.y(), p.z()};
  }
  std::vector<std::uint32_t> byPosition(vertexCount);
  std::iota(byPosition.begin(), byPosition.end(), 0u);
  std::sort(byPosition.begin(), byPosition.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::tie(position[a].x, position[a].y, position[a].z) <
           std::tie(position[b].x, position[b].y, position[b].z);
  });
  std::vector<std::uint32_t> newVertex(vertexCount);
  TriangleHull hull;
  for (std::uint32_t i = 0; i < vertexCount; ++i) {
    newVertex[byPosition[i]] = i;
    hull.vertices.push_back(position[byPosition[i]]);
  }

  struct Face {
    std::array<std::uint32_t, 3> corners;    // new vertex indices
    std::array<std::uint32_t, 3> neighbors;  // old face indices, across edge e
  };
  const std::size_t faceCount = mesh.number_of_faces();
  std::vector<Face> faces(faceCount);
  for (Mesh::Face_index f : mesh.faces()) {
    Face& face = faces[f.idx()];
    Mesh::Halfedge_index h = mesh.halfedge(f);
    for (int e = 0; e < 3; ++e, h = mesh.next(h)) {
      face.corners[e] = newVertex[mesh.source(h).idx()];
      face.neighbors[e] = static_cast<std::uint32_t>(mesh.face(mesh.opposite(h)).idx());
    }
    // Lowest corner first; the edges turn with the corners, so the winding stays.
    const auto lowest =
        std::min_element(face.corners.begin(), face.corners.end()) - face.corners.begin();
    std::rotate(face.corners.begin(), face.corners.begin() + lowest, face.corners.end());
    std::rotate(face.neighbors.begin(), face.neighbors.begin() + lowest, face.neighbors.end());
  }
  std::vector<std::uint32_t> byCorners(faceCount);
  std::iota(byCorners.begin(), byCorners.end(), 0u);
  std::sort(byCorners.begin(), byCorners.end(),
            [&](std::uint32_t a, std::uint32_t b) { return faces[a].corners < faces[b].corners; });
  std::vector<std::uint32_t> newFace(faceCount);
  for (std::uint32_t i = 0; i < faceCount; ++i) newFace[byCorners[i]] = i;
  for (std::uint32_t old : byCorners) {
    hull.triangles.push_back(faces[old].corners);
    hull.neighbors.push_back({newFace[faces[old].neighbors[0]], newFace[faces[old].neighbors[1]],
                              newFace[faces[old].neighbors[2]]});
  }

  if (withSourceIndex) {
    std::unordered_map<PointBits, std::size_t, PointBitsHash> firstIndex;
    firstIndex.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      firstIndex.try_emplace(bitsOf(points[i].x, points[i].y, points[i].z), i);
    }
    hull.sourceIndex.reserve(hull.vertices.size());
    for (const glm::dvec3& v : hull.vertices)
      hull.sourceIndex.push_back(firstIndex.at(bitsOf(v.x, v.y, v.z)));
  }
  return hull;
}

}  // namespace probeproxy::fit
