#include "geometry/level/bsp/bezier_patch.h"

#include <algorithm>
#include <array>

namespace probeproxy {

namespace {

// Quadratic Bernstein weights at t in [0, 1].
std::array<double, 3> bernstein2(double t) {
  const double s = 1.0 - t;
  return {s * s, 2.0 * s * t, t * t};
}

// The piece a grid column (or row) lies in, and its parameter inside that piece. A column on
// a border between two pieces belongs to the lower piece at t = 1: both pieces give the same
// point there, since the border curve depends only on the shared control row.
std::pair<int, double> pieceAndParameter(int gridIndex, int pieces, int subdivisions) {
  const int piece = std::min(gridIndex / subdivisions, pieces - 1);
  const double t = double(gridIndex - piece * subdivisions) / double(subdivisions);
  return {piece, t};
}

}  // namespace

TessellatedPatch tessellateBezierPatch(std::span<const glm::dvec3> controlPoints, int width,
                                       int height, int subdivisions) {
  const int piecesX = (width - 1) / 2;
  const int piecesY = (height - 1) / 2;
  const int columns = piecesX * subdivisions + 1;
  const int rows = piecesY * subdivisions + 1;

  TessellatedPatch patch;
  patch.points.reserve(std::size_t(columns) * rows);
  for (int row = 0; row < rows; ++row) {
    const auto [pieceY, v] = pieceAndParameter(row, piecesY, subdivisions);
    const std::array<double, 3> wy = bernstein2(v);
    for (int column = 0; column < columns; ++column) {
      const auto [pieceX, u] = pieceAndParameter(column, piecesX, subdivisions);
      const std::array<double, 3> wx = bernstein2(u);
      glm::dvec3 point(0.0);
      for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
          const std::size_t c = std::size_t(2 * pieceY + j) * width + std::size_t(2 * pieceX + i);
          point += wy[j] * wx[i] * controlPoints[c];
        }
      }
      patch.points.push_back(point);
    }
  }

  patch.triangles.reserve(std::size_t(columns - 1) * (rows - 1) * 2);
  for (int row = 0; row + 1 < rows; ++row) {
    for (int column = 0; column + 1 < columns; ++column) {
      const unsigned a = unsigned(row * columns + column);  // (column, row)
      const unsigned b = a + 1;                             // (column + 1, row)
      const unsigned c = a + unsigned(columns);             // (column, row + 1)
      const unsigned d = c + 1;                             // (column + 1, row + 1)
      patch.triangles.emplace_back(a, b, d);
      patch.triangles.emplace_back(a, d, c);
    }
  }
  return patch;
}

}  // namespace probeproxy
