#include "geometry/fit/polytope_from_planes.h"

#include "geometry/fit/exact_hull.h"
#include "geometry/fit/fan_apex.h"
#include "geometry/fit/fit_error.h"
#include "geometry/fit/union_find.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

namespace probeproxy {

namespace {

// Corners this close, relative to the polytope's size, are one: 0.4 mm on a 40 m proxy, under
// 0.002 degrees of any reflection seen from 10 m.
constexpr double kCornerMergeRelative = 1e-5;
// Corners closer than this many float epsilons of their coordinates are one too: the mesh is
// written in floats, whose rounding turns an edge that short by up to a quarter degree, and the
// triangle on it with it (downer's layout: two corners 0.13 mm apart at 32 m from the origin
// left a triangle bent inwards by 1.2 degrees, validate's proxy_concave_edge, 0.5 degrees).
// Never more than this, relative to the size, though: a small proxy far from the origin keeps
// its shape (a 1 mm slab 10 km out).
constexpr double kCornerMergeFloatEpsilons = 512.0;
constexpr double kCornerMergeMostRelative = 1e-4;

constexpr double kMinNormalSpread = 1e-3;

bool isFinite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string formatVec(glm::dvec3 v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x + 0.0 << ", " << v.y + 0.0 << ", " << v.z + 0.0 << ")";  // no "-0"
  return s.str();
}

// A hull facet (a, b, c) of the normals that does not have the origin strictly behind it:
// every normal lies behind it, so its outward normal u has dot(u, n_i) <= dot(u, facet) <= 0. A
// facet with the origin less than kMinNormalSpread behind it leaves u nearly open: the planes
// stop a walk along u only after more than 1/kMinNormalSpread times their offsets (a corridor
// closed by a floor tilted by 1e-11, seen on a real map), which no proxy is meant to be.
bool leavesOpen(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  if (fit::orientationSign(a, b, c, glm::dvec3(0.0)) >= 0) return true;
  return glm::dot(glm::normalize(glm::cross(b - a, c - a)), a) < kMinNormalSpread;
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
  for (const auto& [a, b, c] : fit::hullTriangles(normals))
    if (leavesOpen(a, b, c)) return glm::normalize(glm::cross(b - a, c - a));
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

using Triple = std::array<std::size_t, 3>;

// Solves corners from three planes each, in an order that depends on the planes' values, not
// on their indices, so that a corner has the same bits whichever dual triangle asks for it and
// whatever order the planes came in.
class CornerSolver {
 public:
  CornerSolver(const std::vector<ProxyPlane>& planes, const std::vector<double>& heights)
      : planes_(planes), heights_(heights), rank_(planes.size()) {
    std::vector<std::size_t> byValue(planes.size());
    std::iota(byValue.begin(), byValue.end(), std::size_t{0});
    std::stable_sort(byValue.begin(), byValue.end(), [&](std::size_t i, std::size_t j) {
      const ProxyPlane &a = planes[i], &b = planes[j];
      return std::tie(a.normal.x, a.normal.y, a.normal.z, a.offsetMeters) <
             std::tie(b.normal.x, b.normal.y, b.normal.z, b.offsetMeters);
    });
    for (std::size_t r = 0; r < byValue.size(); ++r) rank_[byValue[r]] = r;
  }

  // Planes in value order (equal planes: in index order, and they give the same bits).
  void sort(std::vector<std::size_t>& indices) const {
    std::sort(indices.begin(), indices.end(),
              [&](std::size_t i, std::size_t j) { return rank_[i] < rank_[j]; });
  }

  // The point where three planes meet, relative to the interior point.
  glm::dvec3 corner(std::size_t i, std::size_t j, std::size_t k) const {
    Triple t{i, j, k};
    std::sort(t.begin(), t.end(),
              [&](std::size_t a, std::size_t b) { return rank_[a] < rank_[b]; });
    return solve(t);
  }

  // Of the planes that meet at a corner (in value order, no repeats), the three whose normals
  // are the farthest from dependent, the first such on ties; the corner they give. Every
  // triple up to 40 planes; beyond, the first plane, the one most across it, and the one most
  // across both.
  glm::dvec3 corner(const std::vector<std::size_t>& at) const {
    const std::size_t n = at.size();
    Triple best{0, 1, 2};  // positions in `at`
    double bestConditioning = conditioning(at, best);
    if (n <= 40) {
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
          for (std::size_t k = j + 1; k < n; ++k) {
            const double c = conditioning(at, {i, j, k});
            if (c > bestConditioning) best = {i, j, k}, bestConditioning = c;
          }
        }
      }
    } else {
      const glm::dvec3 first = planes_[at[0]].normal;
      const auto across = [&](std::size_t i) {
        return glm::length(glm::cross(first, planes_[at[i]].normal));
      };
      std::size_t b = 1;
      for (std::size_t i = 2; i < n; ++i) {
        if (across(i) > across(b)) b = i;
      }
      std::size_t c = b == 1 ? 2 : 1;
      for (std::size_t i = 1; i < n; ++i) {
        if (i != b && conditioning(at, {0, b, i}) > conditioning(at, {0, b, c})) c = i;
      }
      best = {0, std::min(b, c), std::max(b, c)};
    }
    return solve({at[best[0]], at[best[1]], at[best[2]]});
  }

 private:
  double conditioning(const std::vector<std::size_t>& at, const Triple& t) const {
    return std::abs(glm::dot(planes_[at[t[0]]].normal,
                             glm::cross(planes_[at[t[1]]].normal, planes_[at[t[2]]].normal)));
  }

  glm::dvec3 solve(const Triple& t) const {
    const glm::dvec3 na = planes_[t[0]].normal, nb = planes_[t[1]].normal,
                     nc = planes_[t[2]].normal;
    const double det = glm::dot(na, glm::cross(nb, nc));
    return (heights_[t[0]] * glm::cross(nb, nc) + heights_[t[1]] * glm::cross(nc, na) +
            heights_[t[2]] * glm::cross(na, nb)) /
           det;
  }

  const std::vector<ProxyPlane>& planes_;
  const std::vector<double>& heights_;
  std::vector<std::size_t> rank_;
};

struct Facet {
  std::size_t plane;
  std::vector<std::uint32_t> corners;  // merged corners' roots, counter-clockwise from outside
};

// A corner of a polytope meets at least three facets. Where planes fitted to a real level meet
// along one line within rounding, the merged corners can put a point of that edge into one
// facet's ring and not its neighbour's (bleach's layout: two corners along a 184 m edge, each
// in one facet only, left the written mesh open there: validate's proxy_not_closed). Such a
// point is on an edge or inside a facet, not a corner: it leaves every ring, and a facet left
// with fewer than three corners (a plane that only touched that edge) leaves with it.
void dropCornersOfFewerThanThreeFacets(std::vector<Facet>& facets) {
  for (bool changed = true; changed;) {
    std::map<std::uint32_t, int> facetsAt;
    for (const Facet& f : facets)
      for (std::uint32_t c : f.corners) ++facetsAt[c];
    changed = false;
    for (Facet& f : facets) {
      const std::size_t before = f.corners.size();
      std::erase_if(f.corners, [&](std::uint32_t c) { return facetsAt[c] < 3; });
      changed = changed || f.corners.size() != before;
    }
    std::erase_if(facets, [](const Facet& f) { return f.corners.size() < 3; });
  }
}

// Whether every edge of a facet's ring is an edge of another facet's ring the other way
// round: a closed boundary.
bool ringsClose(const std::vector<Facet>& facets) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const Facet& f : facets) {
    for (std::size_t j = 0; j < f.corners.size(); ++j)
      edges.emplace(f.corners[j], f.corners[(j + 1) % f.corners.size()]);
  }
  return std::all_of(edges.begin(), edges.end(), [&](const auto& e) {
    return edges.contains({e.second, e.first});
  });
}

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

  const CornerSolver solver(planes, heights);
  const std::size_t cornerCount = dual.triangles.size();
  std::vector<glm::dvec3> fromInterior(cornerCount);  // corner - interior point, per dual facet
  double sizeMeters = 0.0, farthestCoordinate = 0.0;
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
    fromInterior[t] =
        solver.corner(dual.sourceIndex[tri[0]], dual.sourceIndex[tri[1]], dual.sourceIndex[tri[2]]);
    sizeMeters = std::max(sizeMeters, glm::length(fromInterior[t]));
    const glm::dvec3 corner = glm::abs(interior + fromInterior[t]);
    farthestCoordinate = std::max({farthestCoordinate, corner.x, corner.y, corner.z});
  }

  // Where more than three planes meet, the dual facet is split into triangles that give the
  // same corner up to rounding: merge corners that neighbouring dual facets put within
  // `mergeMeters`, and place each at the best conditioned solve of three of the planes that
  // meet there (whichever triangles the dual hull made of them). Planes fitted to a real level
  // also meet a few micrometres apart (two floors tilted 1e-7 apart): kept apart, they leave
  // facets micrometres wide and corners that are one in the mesh's floats, which a mesh check
  // (validate's proxy_degenerate_face, 1e-6 of the size) and engines' importers reject.
  const double floatMergeMeters =
      kCornerMergeFloatEpsilons * std::numeric_limits<float>::epsilon() * farthestCoordinate;
  const double mergeMeters =
      std::max(kCornerMergeRelative * sizeMeters,
               std::min(floatMergeMeters, kCornerMergeMostRelative * sizeMeters));
  fit::UnionFind corners(cornerCount);
  for (std::size_t t = 0; t < cornerCount; ++t) {
    for (std::uint32_t u : dual.neighbors[t]) {
      if (u > t && glm::distance(fromInterior[t], fromInterior[u]) <= mergeMeters) {
        corners.unite(static_cast<std::uint32_t>(t), u);
      }
    }
  }
  std::vector<std::vector<std::size_t>> planesAt(cornerCount);  // by root
  for (std::uint32_t t = 0; t < cornerCount; ++t) {
    auto& at = planesAt[corners.find(t)];
    for (std::uint32_t v : dual.triangles[t]) at.push_back(dual.sourceIndex[v]);
  }
  std::vector<glm::dvec3> cornerFromInterior(cornerCount);  // by root
  for (std::uint32_t t = 0; t < cornerCount; ++t) {
    auto& at = planesAt[t];
    if (at.empty()) continue;
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    solver.sort(at);
    cornerFromInterior[t] = at.size() == 3 ? fromInterior[t] : solver.corner(at);
  }

  // Each dual corner's ring of dual facets is its plane's facet polygon.
  std::vector<std::uint32_t> ringStart(dual.vertices.size(), UINT32_MAX);
  for (std::uint32_t t = 0; t < cornerCount; ++t) {
    for (std::uint32_t v : dual.triangles[t]) {
      if (ringStart[v] == UINT32_MAX) ringStart[v] = t;
    }
  }
  std::vector<Facet> facets;
  std::vector<std::size_t> grazing;  // planes whose facet is a sliver
  std::vector<std::size_t> flat;     // planes whose facet has no area to speak of
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
      const glm::dvec3 p = cornerFromInterior[facet.corners[j]];
      const glm::dvec3 q = cornerFromInterior[facet.corners[(j + 1) % facet.corners.size()]];
      newell += glm::cross(p, q);
    }
    // A facet no wider than the merge distance (twice its area over its longest diagonal) is
    // a plane that only grazes an edge within rounding: its corners lie in a line, and its
    // triangles have no area (bloodprison's layout: three corners along 3.7 m of an edge,
    // 1.2e-5 m off a line in the mesh's floats, validate's proxy_degenerate_face). Left out,
    // with its corners, below.
    double diameter = 0.0;
    for (std::uint32_t a : facet.corners)
      for (std::uint32_t b : facet.corners)
        diameter = std::max(diameter, glm::distance(cornerFromInterior[a], cornerFromInterior[b]));
    if (glm::length(newell) <= mergeMeters * std::max(diameter, mergeMeters)) {
      (glm::length(newell) > mergeMeters * mergeMeters ? grazing : flat).push_back(facet.plane);
      continue;
    }
    if (glm::dot(newell, planes[facet.plane].normal) < 0)
      std::reverse(facet.corners.begin(), facet.corners.end());
    facets.push_back(std::move(facet));
  }
  dropCornersOfFewerThanThreeFacets(facets);
  std::sort(facets.begin(), facets.end(),
            [](const Facet& a, const Facet& b) { return a.plane < b.plane; });
  // A facet of no area is left out as a plane that only touches an edge; but where its
  // neighbours do not meet each other along it they are open there (desertfactory's layout:
  // three planes fitted to one wall 1e-6 apart, the middle one's facet 170 m long and 4e-8 m
  // wide, a hole of 3 open edges once left out). Then its plane goes as a grazing one does.
  const bool closed = ringsClose(facets);
  if (!closed) grazing.insert(grazing.end(), flat.begin(), flat.end());
  if (!grazing.empty() && planes.size() - grazing.size() >= 4) {
    // The corners the grazing planes made are solved again without them.
    std::sort(grazing.begin(), grazing.end());
    std::vector<ProxyPlane> kept;
    std::vector<std::size_t> keptIndex;
    for (std::size_t i = 0; i < planes.size(); ++i) {
      if (std::binary_search(grazing.begin(), grazing.end(), i)) continue;
      kept.push_back(planes[i]);
      keptIndex.push_back(i);
    }
    std::vector<std::size_t> droppedOfKept;
    ConvexProxy proxy = polytopeFromPlanes(std::move(kept), interior, &droppedOfKept);
    if (droppedPlaneIndices != nullptr) {
      *droppedPlaneIndices = grazing;
      for (std::size_t k : droppedOfKept) droppedPlaneIndices->push_back(keptIndex[k]);
      std::sort(droppedPlaneIndices->begin(), droppedPlaneIndices->end());
    }
    return proxy;
  }

  if (!closed) {
    // Engines and validate's proxy_not_closed reject an open mesh: better no proxy (the
    // caller keeps the box) than one with a hole.
    throw FitError("polytope from planes: the " + std::to_string(planes.size()) +
                   " planes leave an open boundary within rounding");
  }
  // Corners sorted by position, so the output does not depend on the hull's internal order.
  std::vector<std::uint32_t> used;
  for (const Facet& f : facets) used.insert(used.end(), f.corners.begin(), f.corners.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  const auto position = [&](std::uint32_t root) { return interior + cornerFromInterior[root]; };
  std::sort(used.begin(), used.end(), [&](std::uint32_t a, std::uint32_t b) {
    const glm::dvec3 pa = position(a), pb = position(b);
    return std::tie(pa.x, pa.y, pa.z) < std::tie(pb.x, pb.y, pb.z);
  });
  std::vector<std::uint32_t> outputIndex(cornerCount, UINT32_MAX);
  if (facets.size() < 4) {
    // Rounding merged what the dual hull kept apart; a proxy without a volume is no proxy.
    throw FitError("polytope from planes: the " + std::to_string(planes.size()) +
                   " planes leave only " + std::to_string(facets.size()) +
                   " facets within rounding");
  }
  ConvexProxy proxy;
  for (std::uint32_t root : used) {
    outputIndex[root] = static_cast<std::uint32_t>(proxy.verticesMeters.size());
    proxy.verticesMeters.push_back(position(root));
  }

  std::size_t nextPlane = 0;
  std::vector<glm::dvec3> facetCorners;  // one facet's, for its fan
  for (const Facet& f : facets) {
    for (; nextPlane < f.plane; ++nextPlane) {
      if (droppedPlaneIndices != nullptr) droppedPlaneIndices->push_back(nextPlane);
    }
    ++nextPlane;
    proxy.planes.push_back(planes[f.plane]);
    facetCorners.clear();
    for (std::uint32_t root : f.corners) facetCorners.push_back(position(root));
    const std::size_t n = f.corners.size(), apex = fanApex(facetCorners);
    for (std::size_t j = 1; j + 1 < n; ++j) {  // a fan: the facet is convex
      proxy.triangles.emplace_back(outputIndex[f.corners[apex]],
                                   outputIndex[f.corners[(apex + j) % n]],
                                   outputIndex[f.corners[(apex + j + 1) % n]]);
    }
  }
  for (; nextPlane < planes.size(); ++nextPlane) {
    if (droppedPlaneIndices != nullptr) droppedPlaneIndices->push_back(nextPlane);
  }
  return proxy;
}

}  // namespace probeproxy
