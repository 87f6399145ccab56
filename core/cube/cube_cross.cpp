#include "core/cube/cube_cross.h"

#include <stdexcept>
#include <string>

namespace probeproxy {

namespace {

struct Cell {
  int col, row;  // in cells
  bool turned;   // 180 degrees
};

// The table in cube_cross.h, in face-index order (px nx py ny pz nz).
Cell cellOf(CrossLayout layout, int face) {
  static constexpr Cell horizontal[kCubeFaceCount] = {{0, 1, false}, {2, 1, false}, {3, 1, false},
                                                      {1, 1, false}, {1, 0, false}, {1, 2, false}};
  static constexpr Cell vertical[kCubeFaceCount] = {{0, 1, false}, {2, 1, false}, {1, 3, true},
                                                    {1, 1, false}, {1, 0, false}, {1, 2, false}};
  return layout == CrossLayout::Horizontal ? horizontal[face] : vertical[face];
}

int cellsWide(CrossLayout layout) { return layout == CrossLayout::Horizontal ? 4 : 3; }
int cellsHigh(CrossLayout layout) { return layout == CrossLayout::Horizontal ? 3 : 4; }

// Index of the first channel of face texel (col, row) in the cross image.
std::size_t imageIndex(CrossLayout layout, int face, int col, int row, int n) {
  const Cell cell = cellOf(layout, face);
  const int c = cell.turned ? n - 1 - col : col;
  const int r = cell.turned ? n - 1 - row : row;
  const std::size_t x = static_cast<std::size_t>(cell.col) * n + c;
  const std::size_t y = static_cast<std::size_t>(cell.row) * n + r;
  return (y * static_cast<std::size_t>(cellsWide(layout)) * n + x) * 3;
}

}  // namespace

RgbImage crossFromCube(const Cubemap& cube, CrossLayout layout, int level) {
  const CubemapLevel& l = cube.levels.at(static_cast<std::size_t>(level));
  const int n = l.faceSize;
  RgbImage image{cellsWide(layout) * n, cellsHigh(layout) * n, {}};
  image.rgb.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0.0f);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const std::size_t from = (static_cast<std::size_t>(row) * n + col) * 3;
        const std::size_t to = imageIndex(layout, f, col, row, n);
        for (int k = 0; k < 3; ++k) image.rgb[to + k] = l.rgb[f][from + k];
      }
    }
  }
  return image;
}

Cubemap cubeFromCross(const RgbImage& image, CrossLayout layout) {
  const int n = image.width / cellsWide(layout);
  if (n < 1 || image.width != cellsWide(layout) * n || image.height != cellsHigh(layout) * n ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw std::invalid_argument(
        "cubeFromCross: " + std::to_string(image.width) + " x " + std::to_string(image.height) +
        " is not a " + (layout == CrossLayout::Horizontal ? "4N x 3N" : "3N x 4N") + " cross");
  }
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    faces[f].resize(static_cast<std::size_t>(n) * n * 3);
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const std::size_t from = imageIndex(layout, f, col, row, n);
        const std::size_t to = (static_cast<std::size_t>(row) * n + col) * 3;
        for (int k = 0; k < 3; ++k) faces[f][to + k] = image.rgb[from + k];
      }
    }
  }
  return Cubemap::fromFaces(n, std::move(faces));
}

}  // namespace probeproxy
