// One of the three translation units that include CGAL (with oriented_box_fit.cpp and
// bounding_sphere_fit.cpp): everything else in geometry/fit reaches CGAL through exact_hull.h.

#include "geometry/fit/exact_hull.h"

#include "geometry/fit/fit_error.h"
#include "geometry/fit/union_find.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_hull_3.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace probeproxy::fit {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Point>;
using Triangulation = CGAL::Triangulation_3<Kernel>;

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
using Triangle = std::array<std::uint32_t, 3>;

bool lexicographicLess(const glm::dvec3& a, const glm::dvec3& b) {
  return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

// The corners of a flat region of hull triangles (all in one plane): its convex polygon with
// no corner on a side, counter-clockwise seen from outside like the triangles, starting at the
// lowest corner by (x, y, z). Exact: the region is projected along a coordinate axis that its
// plane is not parallel to, where exact 2D orientations decide.
std::vector<std::uint32_t> flatRegionCorners(const std::vector<Triangle>& triangles,
                                             const std::vector<std::uint32_t>& members,
                                             const std::vector<glm::dvec3>& position) {
  std::vector<std::uint32_t> corners;
  for (std::uint32_t f : members)
    corners.insert(corners.end(), triangles[f].begin(), triangles[f].end());
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());

  const Triangle& t = triangles[members.front()];
  const glm::dvec3 a = position[t[0]], b = position[t[1]], c = position[t[2]];
  const glm::dvec3 normal = glm::cross(b - a, c - a);
  std::array<int, 3> axes{0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(),
                   [&](int i, int j) { return std::abs(normal[i]) > std::abs(normal[j]); });
  int dropped = -1;
  CGAL::Orientation winding = CGAL::COLLINEAR;
  const auto project = [&](glm::dvec3 p) {
    return Point2(p[(dropped + 1) % 3], p[(dropped + 2) % 3]);
  };
  for (int axis : axes) {
    dropped = axis;
    winding = CGAL::orientation(project(a), project(b), project(c));
    if (winding != CGAL::COLLINEAR) break;
  }
  if (winding == CGAL::COLLINEAR) {
    throw FitError("convex hull: a hull triangle has no area");  // exact predicates: never
  }

  // Andrew's monotone chain on the projections, dropping corners on a side.
  std::vector<std::pair<Point2, std::uint32_t>> sorted;
  sorted.reserve(corners.size());
  for (std::uint32_t v : corners) sorted.emplace_back(project(position[v]), v);
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& i, const auto& j) { return i.first < j.first; });
  std::vector<std::size_t> chain;  // indices into sorted
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = chain.size();
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      const std::size_t i = pass == 0 ? k : sorted.size() - 1 - k;
      while (chain.size() >= start + 2 &&
             CGAL::orientation(sorted[chain[chain.size() - 2]].first, sorted[chain.back()].first,
                               sorted[i].first) != CGAL::LEFT_TURN) {
        chain.pop_back();
      }
      chain.push_back(i);
    }
    chain.pop_back();  // the first corner of the other chain
  }
  std::vector<std::uint32_t> ring;
  ring.reserve(chain.size());
  for (std::size_t i : chain) ring.push_back(sorted[i].second);
  if (winding == CGAL::RIGHT_TURN) std::reverse(ring.begin(), ring.end());
  const auto lowest =
      std::min_element(ring.begin(), ring.end(), [&](std::uint32_t i, std::uint32_t j) {
        return lexicographicLess(position[i], position[j]);
      });
  std::rotate(ring.begin(), lowest, ring.end());
  return ring;
}

PointBits bitsOf(double x, double y, double z) {
  return {std::bit_cast<std::uint64_t>(x), std::bit_cast<std::uint64_t>(y),
          std::bit_cast<std::uint64_t>(z)};
}

// -0 and +0 are one coordinate: + 0.0 makes both +0, so that of two copies of a point which
// differ in the sign of a zero, the hull keeps the same bits whichever comes first.
glm::dvec3 withoutNegativeZero(glm::dvec3 p) { return {p.x + 0.0, p.y + 0.0, p.z + 0.0}; }

std::vector<Point> hullInput(std::span<const glm::dvec3> points) {
  requireFinite(points, "convex hull");
  std::vector<Point> cgalPoints;
  cgalPoints.reserve(points.size());
  for (const glm::dvec3& p : points) cgalPoints.push_back(toCgal(withoutNegativeZero(p)));
  // Repeated points reach a use-after-free in CGAL 5.5's quickhull (CGAL issues #6543, #8625:
  // the farthest point can be one of the three it starts from, and is erased twice). Sorted
  // and unique, the input also has one canonical order, whatever order the caller had.
  std::sort(cgalPoints.begin(), cgalPoints.end());
  cgalPoints.erase(std::unique(cgalPoints.begin(), cgalPoints.end()), cgalPoints.end());
  return cgalPoints;
}

[[noreturn]] void throwNoVolume(std::size_t pointCount) {
  std::ostringstream message;
  message << "convex hull: the " << pointCount << " points span no volume";
  throw FitError(message.str());
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

std::vector<std::array<glm::dvec3, 3>> hullTriangles(std::span<const glm::dvec3> points) {
  const std::vector<Point> cgalPoints = hullInput(points);
  const Triangulation triangulation(cgalPoints.begin(), cgalPoints.end());
  if (triangulation.dimension() < 3) throwNoVolume(points.size());
  const auto at = [](Triangulation::Vertex_handle v) {
    return glm::dvec3(v->point().x(), v->point().y(), v->point().z());
  };
  // Each infinite cell holds one hull facet, the one opposite its infinite vertex; the finite
  // cell across it has its fourth corner strictly inside, which decides the winding.
  std::vector<std::array<glm::dvec3, 3>> triangles;
  for (auto cell = triangulation.all_cells_begin(); cell != triangulation.all_cells_end(); ++cell) {
    if (!triangulation.is_infinite(cell)) continue;
    const int far = cell->index(triangulation.infinite_vertex());
    std::array<glm::dvec3, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = at(cell->vertex((far + 1 + k) % 4));
    const glm::dvec3 inside = at(triangulation.mirror_vertex(cell, far));
    if (orientationSign(t[0], t[1], t[2], inside) > 0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  return triangles;
}

TriangleHull convexHull3(std::span<const glm::dvec3> points, bool withSourceIndex) {
  const std::vector<Point> cgalPoints = hullInput(points);
  Mesh mesh;
  CGAL::convex_hull_3(cgalPoints.begin(), cgalPoints.end(), mesh);
  // Points that span no volume give a polygon, a segment or a point: callers check the span
  // first, so this is the last guard, not the way to find out.
  if (mesh.number_of_faces() < 4 || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
    throwNoVolume(points.size());

  // convex_hull_3 builds a fresh mesh, so indices run 0..n-1 with no removed elements.
  const std::size_t meshVertexCount = mesh.number_of_vertices();
  std::vector<glm::dvec3> position(meshVertexCount);
  for (Mesh::Vertex_index v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    position[v.idx()] = {p.x(), p.y(), p.z()};
  }
  const std::size_t meshFaceCount = mesh.number_of_faces();
  std::vector<Triangle> meshTriangles(meshFaceCount), across(meshFaceCount);
  for (Mesh::Face_index f : mesh.faces()) {
    Mesh::Halfedge_index h = mesh.halfedge(f);
    for (int e = 0; e < 3; ++e, h = mesh.next(h)) {
      meshTriangles[f.idx()][e] = static_cast<std::uint32_t>(mesh.source(h).idx());
      across[f.idx()][e] = static_cast<std::uint32_t>(mesh.face(mesh.opposite(h)).idx());
    }
  }

  // Which triangles CGAL makes of a flat region, and in which order, follow heap addresses
  // (its quickhull keys a map by vertex address), so they change from call to call and from
  // thread to thread (each has its own malloc arena). Keep only what the point set decides:
  // the flat regions (neighbouring triangles in one plane, exactly) and their corners (none on
  // a side or inside, should CGAL keep one), each region fanned from its lowest corner. Then
  // sort corners by position and triangles by corners, so that the same points give the same
  // hull, bit for bit (the facet merging sums areas in this order, the box polish takes the
  // first of equals, the polytope of planes solves corners from these triangles).
  UnionFind regions(meshFaceCount);
  bool anyFlat = false;
  for (std::uint32_t f = 0; f < meshFaceCount; ++f) {
    const Triangle& t = meshTriangles[f];
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = across[f][e];
      if (u < f) continue;
      const std::uint32_t from = t[e], to = t[(e + 1) % 3];
      std::uint32_t apex = meshTriangles[u][0];
      for (std::uint32_t v : meshTriangles[u]) {
        if (v != from && v != to) apex = v;
      }
      if (CGAL::orientation(toCgal(position[t[0]]), toCgal(position[t[1]]), toCgal(position[t[2]]),
                            toCgal(position[apex])) == CGAL::COPLANAR) {
        regions.unite(f, u);
        anyFlat = true;
      }
    }
  }
  std::vector<Triangle> triangles;
  if (!anyFlat) {
    // No flat region, so no corner on a rim or inside one either: CGAL's triangles are the
    // hull's facets.
    triangles = std::move(meshTriangles);
  } else {
    std::vector<std::uint32_t> byRegion(meshFaceCount);
    std::iota(byRegion.begin(), byRegion.end(), 0u);
    std::vector<std::uint32_t> region(meshFaceCount);
    for (std::uint32_t f = 0; f < meshFaceCount; ++f) region[f] = regions.find(f);
    std::sort(byRegion.begin(), byRegion.end(), [&](std::uint32_t a, std::uint32_t b) {
      return std::tie(region[a], a) < std::tie(region[b], b);
    });
    std::vector<std::uint32_t> members;
    for (std::size_t i = 0; i < byRegion.size();) {
      std::size_t j = i;
      while (j < byRegion.size() && region[byRegion[j]] == region[byRegion[i]]) ++j;
      if (j - i == 1) {
        triangles.push_back(meshTriangles[byRegion[i]]);
      } else {
        members.assign(byRegion.begin() + static_cast<std::ptrdiff_t>(i),
                       byRegion.begin() + static_cast<std::ptrdiff_t>(j));
        const std::vector<std::uint32_t> polygon =
            flatRegionCorners(meshTriangles, members, position);
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
          triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
      }
      i = j;
    }
  }

  std::vector<std::uint32_t> kept;
  kept.reserve(meshVertexCount);
  for (const Triangle& t : triangles) kept.insert(kept.end(), t.begin(), t.end());
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  std::sort(kept.begin(), kept.end(), [&](std::uint32_t a, std::uint32_t b) {
    return lexicographicLess(position[a], position[b]);
  });
  std::vector<std::uint32_t> newVertex(meshVertexCount, UINT32_MAX);
  TriangleHull hull;
  hull.vertices.reserve(kept.size());
  for (std::uint32_t i = 0; i < kept.size(); ++i) {
    newVertex[kept[i]] = i;
    hull.vertices.push_back(position[kept[i]]);
  }
  for (Triangle& t : triangles) {
    for (std::uint32_t& v : t) v = newVertex[v];
    // Lowest corner first, keeping the winding.
    const auto lowest = std::min_element(t.begin(), t.end()) - t.begin();
    std::rotate(t.begin(), t.begin() + lowest, t.end());
  }
  std::sort(triangles.begin(), triangles.end());

  // Neighbours from the edges: each directed edge meets its reverse in one other triangle.
  const std::uint64_t vertexCount = hull.vertices.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;  // (from * n + to, triangle)
  edges.reserve(3 * triangles.size());
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    for (int e = 0; e < 3; ++e)
      edges.emplace_back(triangles[i][e] * vertexCount + triangles[i][(e + 1) % 3], i);
  }
  std::sort(edges.begin(), edges.end());
  hull.neighbors.resize(triangles.size());
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    for (int e = 0; e < 3; ++e) {
      const std::uint64_t reverse = triangles[i][(e + 1) % 3] * vertexCount + triangles[i][e];
      const auto it = std::lower_bound(edges.begin(), edges.end(),
                                       std::pair<std::uint64_t, std::uint32_t>(reverse, 0u));
      if (it == edges.end() || it->first != reverse) {
        throw FitError("convex hull: the hull of the " + std::to_string(points.size()) +
                       " points is not closed after merging its flat regions");
      }
      hull.neighbors[i][e] = it->second;
    }
  }
  hull.triangles = std::move(triangles);

  if (withSourceIndex) {
    std::unordered_map<PointBits, std::size_t, PointBitsHash> firstIndex;
    firstIndex.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const glm::dvec3 p = withoutNegativeZero(points[i]);
      firstIndex.try_emplace(bitsOf(p.x, p.y, p.z), i);
    }
    hull.sourceIndex.reserve(hull.vertices.size());
    for (const glm::dvec3& v : hull.vertices)
      hull.sourceIndex.push_back(firstIndex.at(bitsOf(v.x, v.y, v.z)));
  }
  return hull;
}

}  // namespace probeproxy::fit
