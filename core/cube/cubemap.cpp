#include "core/cube/cubemap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace probeproxy {

int fullMipCount(int faceSize) {
  if (faceSize < 1) throw std::invalid_argument("cubemap face size must be at least 1");
  int count = 1;
  while (faceSize > 1) {
    faceSize /= 2;
    ++count;
  }
  return count;
}

Cubemap Cubemap::fromFaces(int faceSize, std::array<std::vector<float>, kCubeFaceCount> rgb) {
  if (faceSize < 1) {
    throw std::invalid_argument("Cubemap::fromFaces: face size " + std::to_string(faceSize) +
                                " is below 1");
  }
  const std::size_t expected = static_cast<std::size_t>(faceSize) * faceSize * 3;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    if (rgb[f].size() != expected) {
      throw std::invalid_argument(
          "Cubemap::fromFaces: face " + std::string(cubeFaceName(CubeFace(f))) + " holds " +
          std::to_string(rgb[f].size()) + " floats, expected " + std::to_string(expected));
    }
    for (float value : rgb[f]) {
      if (!std::isfinite(value)) {
        throw std::invalid_argument("Cubemap::fromFaces: face " +
                                    std::string(cubeFaceName(CubeFace(f))) +
                                    " holds a non-finite value");
      }
    }
  }
  Cubemap cube;
  cube.levels.resize(1);
  cube.levels[0].faceSize = faceSize;
  cube.levels[0].rgb = std::move(rgb);
  return cube;
}

namespace {

// Child texels overlapped by parent texel `p` along one axis and their weights (fractions of a
// child texel covered), for a child size n and parent size m. Weights sum to n / m.
struct Span {
  int first = 0;
  std::vector<double> weights;
};

Span coverSpan(int p, int n, int m) {
  // Parent p covers [p * n / m, (p + 1) * n / m) in child units; exact in rationals.
  const double lo = static_cast<double>(p) * n / m;
  const double hi = static_cast<double>(p + 1) * n / m;
  Span span;
  span.first = static_cast<int>(std::floor(lo));
  const int last = std::min(n - 1, static_cast<int>(std::ceil(hi)) - 1);
  for (int c = span.first; c <= last; ++c) {
    const double w = std::min(hi, c + 1.0) - std::max(lo, static_cast<double>(c));
    span.weights.push_back(w);
  }
  return span;
}

CubemapLevel downsample(const CubemapLevel& child) {
  const int n = child.faceSize;
  const int m = std::max(1, n / 2);
  std::vector<Span> spans;
  spans.reserve(static_cast<std::size_t>(m));
  for (int p = 0; p < m; ++p) spans.push_back(coverSpan(p, n, m));
  const double area = (static_cast<double>(n) / m) * (static_cast<double>(n) / m);

  CubemapLevel parent;
  parent.faceSize = m;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const std::vector<float>& src = child.rgb[f];
    std::vector<float>& dst = parent.rgb[f];
    dst.assign(static_cast<std::size_t>(m) * m * 3, 0.0f);
    for (int pr = 0; pr < m; ++pr) {
      const Span& rows = spans[static_cast<std::size_t>(pr)];
      for (int pc = 0; pc < m; ++pc) {
        const Span& cols = spans[static_cast<std::size_t>(pc)];
        double sum[3] = {0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < rows.weights.size(); ++i) {
          const int r = rows.first + static_cast<int>(i);
          for (std::size_t j = 0; j < cols.weights.size(); ++j) {
            const int c = cols.first + static_cast<int>(j);
            const double w = rows.weights[i] * cols.weights[j];
            const std::size_t at = (static_cast<std::size_t>(r) * n + c) * 3;
            for (int k = 0; k < 3; ++k) sum[k] += w * src[at + k];
          }
        }
        const std::size_t out = (static_cast<std::size_t>(pr) * m + pc) * 3;
        for (int k = 0; k < 3; ++k) dst[out + k] = static_cast<float>(sum[k] / area);
      }
    }
  }
  return parent;
}

}  // namespace

void Cubemap::buildMipChain() {
  if (levels.empty()) throw std::logic_error("Cubemap::buildMipChain: the cubemap has no level 0");
  levels.resize(1);
  levels.reserve(static_cast<std::size_t>(fullMipCount(levels[0].faceSize)));
  while (levels.back().faceSize > 1) levels.push_back(downsample(levels.back()));
}

glm::vec3 Cubemap::texel(CubeFace face, int level, int col, int row) const {
  if (level < 0 || level >= numLevels()) {
    throw std::out_of_range("Cubemap::texel: level " + std::to_string(level) + " of " +
                            std::to_string(numLevels()));
  }
  const CubemapLevel& l = levels[static_cast<std::size_t>(level)];
  const int f = static_cast<int>(face);
  if (f < 0 || f >= kCubeFaceCount || col < 0 || row < 0 || col >= l.faceSize ||
      row >= l.faceSize) {
    throw std::out_of_range("Cubemap::texel: texel (" + std::to_string(col) + ", " +
                            std::to_string(row) + ") outside a " + std::to_string(l.faceSize) +
                            " face");
  }
  const std::size_t at = (static_cast<std::size_t>(row) * l.faceSize + col) * 3;
  return {l.rgb[f][at], l.rgb[f][at + 1], l.rgb[f][at + 2]};
}

}  // namespace probeproxy
