#include "geometry/fit/polytope_from_planes.h"

#include "geometry/fit/exact_hull.h"
#include "geometry/fit/fit_error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>

namespace probeproxy {

namespace {

bool isFinite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string formatVec(glm::dvec3 v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// A direction in which nothing stops the intersection (dot(n_i, v) <= 0 for every normal), or
// nothing when the normals positively span space (the origin strictly inside their hull).
std::optional<glm::dvec3> openDirection(std::span<const glm::dvec3> normals) {
  const fit::AffineSpan span = fit::affineSpan(normals);
  const auto& w = span.witnesses;
  switch (span.dimension) {
    case -1:
      return glm::dvec3(1, 0, 0);
    case 0:  // one normal, repeated: straight against it
      return glm::length(normals[0]) > 0 ? -glm::normalize(normals[0]) : glm::dvec3(1, 0, 0);
    case 1: {  // normals on a line: v orthogonal to the plane through the line and the origin
      const glm::dvec3 a = normals[w[0]], b = normals[w[1]];
      const glm::dvec3 c = glm::cross(a, b);
      if (glm::length(c) > 0) return glm::normalize(c);
      const glm::dvec3 along = b - a;  // the line passes through the origin: any normal to it
      const glm::dvec3 other =
          std::abs(along.x) < std::abs(along.z) ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
      return glm::normalize(glm::cross(along, other));
    }
    case 2: {  // normals on a plane dot(u, n) = e: -u when the plane misses the origin, else u
      const glm::dvec3 a = normals[w[0]];
      const glm::dvec3 u = glm::normalize(glm::cross(normals[w[1]] - a, normals[w[2]] - a));
      return glm::dot(u, a) > 0 ? -u : u;
    }
    default:
      break;
  }
  // A hull facet that does not have the origin strictly behind it: every normal lies behind
  // it, so its outward normal u has dot(u, n_i) <= dot(u, facet) <= 0.
  const fit::TriangleHull hull = fit::convexHull3(normals);
  for (const auto& t : hull.triangles) {
    const glm::dvec3 a = hull.vertices[t[0]], b = hull.vertices[t[1]], c = hull.vertices[t[2]];
    if (fit::orientationSign(a, b, c, glm::dvec3(0.0)) >= 0)
      return glm::normalize(glm::cross(b - a, c - a));
  }
  return std::nullopt;
}

void checkPlanes(const std::vector<ProxyPlane>& planes, glm::dvec3 interior) {
  if (!isFinite(interior)) {
    throw FitError("polytope from planes: the interior point " + formatVec(interior) +
                   " is not finite");
  }
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const double length = glm::length(planes[i].normal);
    if (!isFinite(planes[i].normal) || !std::isfinite(planes[i].offsetMeters) ||
        std::abs(length - 1.0) > 1e-6) {
      std::ostringstream message;
      message << "polytope from planes: plane " << i << " of " << planes.size() << " has normal "
              << formatVec(planes[i].normal) << " (length " << length << ") and offset "
              << planes[i].offsetMeters << " m; it needs a finite unit normal and a finite offset";
      throw FitError(message.str());
    }
  }
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

bool isBounded(const std::vector<ProxyPlane>& planes) {
  if (planes.size() < 4) return false;
  std::vector<glm::dvec3> normals;
  normals.reserve(planes.size());
  for (const ProxyPlane& p : planes) {
    if (!isFinite(p.normal)) return false;
    normals.push_back(p.normal);
  }
  return !openDirection(normals).has_value();
}

ConvexProxy polytopeFromPlanes(std::vector<ProxyPlane> planes, glm::dvec3 interior,
                               std::vector<std::size_t>* droppedPlaneIndices) {
  if (droppedPlaneIndices != nullptr) droppedPlaneIndices->clear();
  checkPlanes(planes, interior);
  std::vector<glm::dvec3> normals;
  for (const ProxyPlane& p : planes) normals.push_back(p.normal);
  if (const auto open = openDirection(normals)) {
    std::ostringstream message;
    message << "polytope from planes: the " << planes.size()
            << " planes bound no volume: nothing stops it in direction " << formatVec(*open);
    throw FitError(message.str());
  }

  // Heights of the planes above the interior point, which must be positive beyond the rounding
  // of computing them: the dual below divides by them.
  std::vector<double> heights(planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const glm::dvec3 n = planes[i].normal;
    const double h = planes[i].offsetMeters - glm::dot(n, interior);
    const double rounding = 32 * std::numeric_limits<double>::epsilon() *
                            (std::abs(planes[i].offsetMeters) + std::abs(n.x * interior.x) +
                             std::abs(n.y * interior.y) + std::abs(n.z * interior.z));
    if (!(h > rounding)) {
      std::ostringstream message;
      message << "polytope from planes: the interior point " << formatVec(interior)
              << " is not strictly inside plane " << i << " (normal " << formatVec(n) << ", offset "
              << planes[i].offsetMeters << " m): it lies " << -h << " m outside";
      throw FitError(message.str());
    }
    heights[i] = h;
  }

  // The dual: plane i becomes the point n_i / h_i. Planes that bound a facet become corners of
  // the dual hull, redundant ones fall inside it, and each dual facet (three planes) is a
  // corner of the polytope. This is halfspace_intersection_3's method, done here so that the
  // planes behind each corner and facet stay known.
  std::vector<glm::dvec3> dualPoints(planes.size());
  for (std::size_t i = 0; i < planes.size(); ++i) dualPoints[i] = planes[i].normal / heights[i];
  const fit::TriangleHull dual = fit::convexHull3(dualPoints, /*withSourceIndex=*/true);

  const std::size_t cornerCount = dual.triangles.size();
  std::vector<glm::dvec3> fromInterior(cornerCount);  // corner - interior point
  std::vector<double> conditioning(cornerCount);
  double sizeMeters = 0.0;
  for (std::size_t t = 0; t < cornerCount; ++t) {
    const auto& tri = dual.triangles[t];
    if (fit::orientationSign(dual.vertices[tri[0]], dual.vertices[tri[1]], dual.vertices[tri[2]],
                             glm::dvec3(0.0)) >= 0) {
      std::ostringstream message;
      message << "polytope from planes: the " << planes.size()
              << " planes bound no volume within rounding (their normals nearly leave a direction "
                 "open)";
      throw FitError(message.str());
    }
    const std::size_t a = dual.sourceIndex[tri[0]], b = dual.sourceIndex[tri[1]],
                      c = dual.sourceIndex[tri[2]];
    const glm::dvec3 na = planes[a].normal, nb = planes[b].normal, nc = planes[c].normal;
    const double det = glm::dot(na, glm::cross(nb, nc));
    fromInterior[t] = (heights[a] * glm::cross(nb, nc) + heights[b] * glm::cross(nc, na) +
                       heights[c] * glm::cross(na, nb)) /
                      det;
    conditioning[t] = std::abs(det);
    sizeMeters = std::max(sizeMeters, glm::length(fromInterior[t]));
  }

  // Where more than three planes meet, the dual facet is split into triangles that give the
  // same corner up to rounding: merge corners that neighbouring dual facets put within
  // `mergeMeters`, and place each at its best conditioned solve.
  const double mergeMeters = 1e-9 * sizeMeters;
  UnionFind corners(cornerCount);
  for (std::size_t t = 0; t < cornerCount; ++t) {
    for (std::uint32_t u : dual.neighbors[t]) {
      if (u > t && glm::distance(fromInterior[t], fromInterior[u]) <= mergeMeters) {
        corners.unite(static_cast<std::uint32_t>(t), u);
      }
    }
  }
  std::vector<std::uint32_t> best(cornerCount);
  for (std::uint32_t t = 0; t < cornerCount; ++t) {
    const std::uint32_t root = corners.find(t);
    if (t == root || conditioning[t] > conditioning[best[root]]) best[root] = t;
  }

  // Each dual corner's ring of dual facets is its plane's facet polygon.
  std::vector<std::uint32_t> ringStart(dual.vertices.size(), UINT32_MAX);
  for (std::uint32_t t = 0; t < cornerCount; ++t) {
    for (std::uint32_t v : dual.triangles[t]) {
      if (ringStart[v] == UINT32_MAX) ringStart[v] = t;
    }
  }
  struct Facet {
    std::size_t plane;
    std::vector<std::uint32_t> corners;  // roots, counter-clockwise seen from outside
  };
  std::vector<Facet> facets;
  for (std::uint32_t v = 0; v < dual.vertices.size(); ++v) {
    Facet facet{dual.sourceIndex[v], {}};
    std::uint32_t t = ringStart[v];
    for (std::size_t steps = 0; steps <= cornerCount; ++steps) {
      const std::uint32_t root = corners.find(t);
      if (facet.corners.empty() || facet.corners.back() != root) facet.corners.push_back(root);
      const auto& tri = dual.triangles[t];
      const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      t = dual.neighbors[t][(k + 2) % 3];  // across the edge that ends at v
      if (t == ringStart[v]) break;
    }
    while (facet.corners.size() > 1 && facet.corners.front() == facet.corners.back())
      facet.corners.pop_back();
    if (facet.corners.size() < 3) continue;  // the plane touches an edge or a corner only

    glm::dvec3 newell(0.0);
    for (std::size_t j = 0; j < facet.corners.size(); ++j) {
      const glm::dvec3 p = fromInterior[best[facet.corners[j]]];
      const glm::dvec3 q = fromInterior[best[facet.corners[(j + 1) % facet.corners.size()]]];
      newell += glm::cross(p, q);
    }
    if (glm::length(newell) <= mergeMeters * mergeMeters) continue;
    if (glm::dot(newell, planes[facet.plane].normal) < 0)
      std::reverse(facet.corners.begin(), facet.corners.end());
    facets.push_back(std::move(facet));
  }
  std::sort(facets.begin(), facets.end(),
            [](const Facet& a, const Facet& b) { return a.plane < b.plane; });

  // Corners sorted by position, so the output does not depend on the hull's internal order.
  std::vector<std::uint32_t> used;
  for (const Facet& f : facets) used.insert(used.end(), f.corners.begin(), f.corners.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  const auto position = [&](std::uint32_t root) { return interior + fromInterior[best[root]]; };
  std::sort(used.begin(), used.end(), [&](std::uint32_t a, std::uint32_t b) {
    const glm::dvec3 pa = position(a), pb = position(b);
    return std::tie(pa.x, pa.y, pa.z) < std::tie(pb.x, pb.y, pb.z);
  });
  std::vector<std::uint32_t> outputIndex(cornerCount, UINT32_MAX);
  ConvexProxy proxy;
  for (std::uint32_t root : used) {
    outputIndex[root] = static_cast<std::uint32_t>(proxy.verticesMeters.size());
    proxy.verticesMeters.push_back(position(root));
  }

  std::size_t nextPlane = 0;
  for (const Facet& f : facets) {
    for (; nextPlane < f.plane; ++nextPlane) {
      if (droppedPlaneIndices != nullptr) droppedPlaneIndices->push_back(nextPlane);
    }
    ++nextPlane;
    proxy.planes.push_back(planes[f.plane]);
    for (std::size_t j = 1; j + 1 < f.corners.size(); ++j) {  // a fan: the facet is convex
      proxy.triangles.emplace_back(outputIndex[f.corners[0]], outputIndex[f.corners[j]],
                                   outputIndex[f.corners[j + 1]]);
    }
  }
  for (; nextPlane < planes.size(); ++nextPlane) {
    if (droppedPlaneIndices != nullptr) droppedPlaneIndices->push_back(nextPlane);
  }
  return proxy;
}

}  // namespace probeproxy
