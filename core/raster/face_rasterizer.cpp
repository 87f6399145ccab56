#include "core/raster/face_rasterizer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace probeproxy {

namespace {

struct ClipVertex {
  glm::dvec3 camera;  // x right, y up, z forward, metres from the eye
  glm::dvec3 attribute;
};

struct ScreenVertex {
  double x = 0, y = 0;  // texels, x right, y down; texel (c, r) has its centre at (c+.5, r+.5)
  double inverseZ = 0;  // 1 / camera z, linear in screen space
  glm::dvec3 attributeOverZ{0.0};
};

// The edge function of a -> b at p: positive on the left of a -> b in y-down screen space (the
// inside of a triangle whose vertices run clockwise on screen). Evaluated from the endpoint that
// sorts first, so the two triangles sharing an edge get exactly opposite values and no texel
// centre is counted twice or dropped by rounding.
double edgeFunction(const ScreenVertex& a, const ScreenVertex& b, double px, double py) {
  const bool aFirst = a.x < b.x || (a.x == b.x && a.y < b.y);
  const ScreenVertex& s = aFirst ? a : b;
  const ScreenVertex& e = aFirst ? b : a;
  const double value = (e.x - s.x) * (py - s.y) - (e.y - s.y) * (px - s.x);
  return aFirst ? value : -value;
}

// Top-left rule for clockwise-on-screen triangles in y-down space: left edges run upwards,
// top edges are horizontal and run to the right.
bool isTopLeft(const ScreenVertex& a, const ScreenVertex& b) {
  const double dy = b.y - a.y;
  return dy < 0 || (dy == 0 && b.x > a.x);
}

bool covers(double edge, bool topLeft) { return edge > 0 || (edge == 0 && topLeft); }

void drawScreenTriangle(ScreenVertex v0, ScreenVertex v1, ScreenVertex v2, FaceTarget& target) {
  double area = edgeFunction(v0, v1, v2.x, v2.y);
  if (area == 0 || !std::isfinite(area)) return;
  if (area < 0) {
    std::swap(v1, v2);
    area = -area;
  }
  const int n = target.faceSize;
  const double minX = std::min({v0.x, v1.x, v2.x}), maxX = std::max({v0.x, v1.x, v2.x});
  const double minY = std::min({v0.y, v1.y, v2.y}), maxY = std::max({v0.y, v1.y, v2.y});
  // Texel centres c + 0.5 inside [min, max].
  const int colBegin = static_cast<int>(std::max(0.0, std::ceil(minX - 0.5)));
  const int colEnd = static_cast<int>(std::min<double>(n - 1, std::floor(maxX - 0.5)));
  const int rowBegin = static_cast<int>(std::max(0.0, std::ceil(minY - 0.5)));
  const int rowEnd = static_cast<int>(std::min<double>(n - 1, std::floor(maxY - 0.5)));
  const bool topLeft01 = isTopLeft(v0, v1), topLeft12 = isTopLeft(v1, v2),
             topLeft20 = isTopLeft(v2, v0);
  for (int row = rowBegin; row <= rowEnd; ++row) {
    const double py = row + 0.5;
    for (int col = colBegin; col <= colEnd; ++col) {
      const double px = col + 0.5;
      const double e12 = edgeFunction(v1, v2, px, py);
      const double e20 = edgeFunction(v2, v0, px, py);
      const double e01 = edgeFunction(v0, v1, px, py);
      if (!covers(e12, topLeft12) || !covers(e20, topLeft20) || !covers(e01, topLeft01)) continue;
      const std::size_t i = static_cast<std::size_t>(row) * n + col;
      if (target.covered[i]) continue;
      // Screen-space barycentrics weight attribute / z and 1 / z, both linear on screen.
      const double l0 = e12 / area, l1 = e20 / area, l2 = e01 / area;
      const double inverseZ = l0 * v0.inverseZ + l1 * v1.inverseZ + l2 * v2.inverseZ;
      if (!(inverseZ > 0)) continue;
      target.attribute[i] =
          (l0 * v0.attributeOverZ + l1 * v1.attributeOverZ + l2 * v2.attributeOverZ) / inverseZ;
      target.covered[i] = 1;
    }
  }
}

// The crossing of the near plane on a -> b, computed from the endpoint that sorts first so an
// edge shared by two triangles is clipped to the same point in both.
ClipVertex nearCrossing(const ClipVertex& a, const ClipVertex& b, double nearMeters) {
  const bool aFirst =
      a.camera.z < b.camera.z ||
      (a.camera.z == b.camera.z &&
       (a.camera.x < b.camera.x || (a.camera.x == b.camera.x && a.camera.y < b.camera.y)));
  const ClipVertex& s = aFirst ? a : b;
  const ClipVertex& e = aFirst ? b : a;
  const double t = (nearMeters - s.camera.z) / (e.camera.z - s.camera.z);
  ClipVertex out{s.camera + t * (e.camera - s.camera),
                 s.attribute + t * (e.attribute - s.attribute)};
  out.camera.z = nearMeters;
  return out;
}

}  // namespace

FaceTarget emptyFaceTarget(int faceSize) {
  if (faceSize < 1) throw std::invalid_argument("face target size must be at least 1");
  const auto texels = static_cast<std::size_t>(faceSize) * static_cast<std::size_t>(faceSize);
  return {faceSize, std::vector<glm::dvec3>(texels, glm::dvec3(0.0)),
          std::vector<std::uint8_t>(texels, 0)};
}

void rasterizeTriangle(CubeFace face, glm::dvec3 eye, double nearMeters,
                       const std::array<RasterVertex, 3>& triangle, FaceTarget& target) {
  if (!(nearMeters > 0)) throw std::invalid_argument("near plane distance must be positive");
  const CubeFaceAxes& axes = cubeFaceAxes()[static_cast<int>(face)];
  const glm::dvec3 right(axes.right), up(axes.up), forward(axes.forward);

  // Sutherland-Hodgman against z >= near: a triangle becomes at most a quad.
  ClipVertex in[3];
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 rel = triangle[k].positionMeters - eye;
    in[k] = {{glm::dot(rel, right), glm::dot(rel, up), glm::dot(rel, forward)},
             triangle[k].attribute};
  }
  ClipVertex polygon[4];
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    const ClipVertex& a = in[k];
    const ClipVertex& b = in[(k + 1) % 3];
    const bool aIn = a.camera.z >= nearMeters, bIn = b.camera.z >= nearMeters;
    if (aIn) polygon[count++] = a;
    if (aIn != bIn) polygon[count++] = nearCrossing(a, b, nearMeters);
  }
  if (count < 3) return;

  const double half = 0.5 * target.faceSize;
  ScreenVertex screen[4];
  for (int k = 0; k < count; ++k) {
    const ClipVertex& c = polygon[k];
    const double inverseZ = 1.0 / c.camera.z;
    screen[k] = {(c.camera.x * inverseZ + 1.0) * half, (1.0 - c.camera.y * inverseZ) * half,
                 inverseZ, c.attribute * inverseZ};
  }
  for (int k = 1; k + 1 < count; ++k)
    drawScreenTriangle(screen[0], screen[k], screen[k + 1], target);
}

}  // namespace probeproxy
