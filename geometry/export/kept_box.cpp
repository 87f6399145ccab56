#include "geometry/export/kept_box.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace probeproxy {

namespace {

// Opposite enough to pair, square enough to be a box's axes; the corner test is the real one.
constexpr double kPairCosine = -0.999;
constexpr double kSquareCosine = 0.001;

// Largest distance from a point of one set to the nearest point of the other, both ways.
double hausdorff(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  const auto oneWay = [](const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to) {
    double worst = 0.0;
    for (const glm::dvec3& p : from) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const glm::dvec3& q : to) nearest = std::min(nearest, glm::distance(p, q));
      worst = std::max(worst, nearest);
    }
    return worst;
  };
  return std::max(oneWay(a, b), oneWay(b, a));
}

// The box with these (orthonormal, right-handed) axes that spans the corners.
BoxShape spanningBox(const std::vector<glm::dvec3>& corners, const glm::dmat3& axes) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity());
  glm::dvec3 hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& c : corners) {
    const glm::dvec3 local = glm::transpose(axes) * c;
    lo = glm::min(lo, local);
    hi = glm::max(hi, local);
  }
  BoxShape box;
  box.centerMeters = axes * ((lo + hi) / 2.0);
  box.halfExtentsMeters = (hi - lo) / 2.0;
  box.worldFromBox = glm::normalize(glm::quat_cast(axes));
  return box;
}

}  // namespace

std::optional<BoxShape> boxOfConvex(const ConvexProxy& convex) {
  const std::vector<ProxyPlane>& planes = convex.planes;
  if (planes.size() != 6) return std::nullopt;

  // Three opposite pairs, each as (outward +a plane, outward -a plane).
  std::array<std::array<int, 2>, 3> pairs{};
  std::array<bool, 6> used{};
  int pairCount = 0;
  for (int i = 0; i < 6; ++i) {
    if (used[i]) continue;
    int best = -1;
    for (int j = i + 1; j < 6; ++j) {
      if (used[j]) continue;
      if (best < 0 || glm::dot(planes[i].normal, planes[j].normal) <
                          glm::dot(planes[i].normal, planes[best].normal)) {
        best = j;
      }
    }
    if (best < 0 || glm::dot(planes[i].normal, planes[best].normal) > kPairCosine) {
      return std::nullopt;
    }
    used[i] = used[best] = true;
    pairs[pairCount++] = {i, best};
  }
  std::array<glm::dvec3, 3> axis;
  for (int k = 0; k < 3; ++k) {
    axis[k] = glm::normalize(planes[pairs[k][0]].normal - planes[pairs[k][1]].normal);
  }
  for (int k = 0; k < 3; ++k) {
    if (std::abs(glm::dot(axis[k], axis[(k + 1) % 3])) > kSquareCosine) return std::nullopt;
  }

  // The eight corners: one plane of each pair.
  std::vector<glm::dvec3> corners;
  for (int c = 0; c < 8; ++c) {
    glm::dmat3 rows;
    glm::dvec3 offsets;
    for (int k = 0; k < 3; ++k) {
      const ProxyPlane& p = planes[pairs[k][(c >> k) & 1]];
      rows[k] = p.normal;
      offsets[k] = p.offsetMeters;
    }
    // rows holds the normals as columns; the system is rows^T x = offsets.
    corners.push_back(glm::inverse(glm::transpose(rows)) * offsets);
  }
  for (const glm::dvec3& c : corners) {
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return std::nullopt;
  }

  const BoxShape aligned = spanningBox(corners, glm::dmat3(1.0));
  if (hausdorff(convexFromBox(aligned).verticesMeters, corners) <= kBoxCornerToleranceMeters) {
    BoxShape box = aligned;
    box.worldFromBox = glm::dquat(1, 0, 0, 0);  // exactly: an `aabb`
    return box;
  }

  // Pair axes to world axes: the permutation with the largest sum of |cosines|, first wins.
  std::array<int, 3> order{0, 1, 2}, bestOrder = order;
  double bestScore = -1.0;
  do {
    double score = 0.0;
    for (int k = 0; k < 3; ++k) score += std::abs(axis[order[k]][k]);
    if (score > bestScore) {
      bestScore = score;
      bestOrder = order;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  glm::dvec3 u0 = axis[bestOrder[0]], u1 = axis[bestOrder[1]];
  if (u0.x < 0) u0 = -u0;
  if (u1.y < 0) u1 = -u1;
  u1 = glm::normalize(u1 - glm::dot(u1, u0) * u0);  // Gram-Schmidt: exactly square
  const glm::dmat3 axes(u0, u1, glm::cross(u0, u1));
  const BoxShape oriented = spanningBox(corners, axes);
  if (hausdorff(convexFromBox(oriented).verticesMeters, corners) <= kBoxCornerToleranceMeters) {
    return oriented;
  }
  return std::nullopt;
}

std::optional<BoxShape> keptBox(const ProxyShape& shape) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) return *box;
  if (const auto* convex = std::get_if<ConvexProxy>(&shape)) return boxOfConvex(*convex);
  return std::nullopt;
}

}  // namespace probeproxy
