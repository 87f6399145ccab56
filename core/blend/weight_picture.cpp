#include "core/blend/weight_picture.h"

#include "core/blend/influence_factor.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace probeproxy {

glm::u8vec3 probeColour(int probe) {
  static constexpr std::array<glm::u8vec3, 8> kPalette = {{{255, 0, 0},
                                                           {0, 255, 0},
                                                           {0, 0, 255},
                                                           {255, 200, 0},
                                                           {0, 220, 255},
                                                           {255, 0, 220},
                                                           {255, 120, 0},
                                                           {140, 80, 255}}};
  return kPalette[static_cast<std::size_t>(probe) % kPalette.size()];
}

WeightPicture renderWeightPicture(std::span<const InfluenceVolume> volumes, double zMeters,
                                  const BlendOptions& options, int longSidePixels,
                                  std::span<const glm::dvec3> markersMeters) {
  if (volumes.empty()) throw std::invalid_argument("weight picture: no influence volume");
  if (longSidePixels < 16) throw std::invalid_argument("weight picture: under 16 pixels");
  glm::dvec3 lo, hi;
  influenceBounds(volumes, lo, hi);
  constexpr double kMarginMeters = 0.5;
  const glm::dvec2 extent = glm::dvec2(hi - lo) + 2.0 * kMarginMeters;
  WeightPicture picture;
  picture.metersPerPixel = std::max(extent.x, extent.y) / longSidePixels;
  picture.width = std::max(1, static_cast<int>(std::ceil(extent.x / picture.metersPerPixel)));
  picture.height = std::max(1, static_cast<int>(std::ceil(extent.y / picture.metersPerPixel)));
  picture.minMeters = glm::dvec2(lo) - kMarginMeters;

  const std::size_t pixels = static_cast<std::size_t>(picture.width) * picture.height;
  // Per pixel: which volumes cover it and whose inner range it is in, as bit masks, for the
  // outlines (a volume's boundary runs between two pixels that disagree).
  std::vector<std::uint64_t> outer(pixels, 0), inner(pixels, 0);
  std::vector<glm::dvec3> colour(pixels, glm::dvec3(0.0));
  for (int row = 0; row < picture.height; ++row) {
    for (int col = 0; col < picture.width; ++col) {
      const glm::dvec3 p(
          picture.minMeters.x + (col + 0.5) * picture.metersPerPixel,
          picture.minMeters.y + (picture.height - row - 0.5) * picture.metersPerPixel, zMeters);
      const std::size_t i = static_cast<std::size_t>(row) * picture.width + col;
      for (std::size_t v = 0; v < volumes.size() && v < 64; ++v) {
        const double a = normalizedDistance(volumes[v], p);
        if (a < 1.0) outer[i] |= std::uint64_t{1} << v;
        if (a == 0.0) inner[i] |= std::uint64_t{1} << v;
      }
      for (const ProbeWeight& w : blendWeights(volumes, p, options)) {
        colour[i] += w.weight * glm::dvec3(probeColour(w.probe));
      }
    }
  }
  picture.rgb8.resize(pixels * 3);
  for (int row = 0; row < picture.height; ++row) {
    for (int col = 0; col < picture.width; ++col) {
      const std::size_t i = static_cast<std::size_t>(row) * picture.width + col;
      const auto differs = [&](const std::vector<std::uint64_t>& mask) {
        return (col + 1 < picture.width && mask[i] != mask[i + 1]) ||
               (row + 1 < picture.height && mask[i] != mask[i + picture.width]);
      };
      glm::dvec3 c = glm::clamp(glm::round(colour[i]), 0.0, 255.0);
      if (differs(inner)) c = glm::dvec3(128.0);
      if (differs(outer)) c = glm::dvec3(255.0);
      for (int k = 0; k < 3; ++k) picture.rgb8[i * 3 + k] = static_cast<std::uint8_t>(c[k]);
    }
  }
  for (const glm::dvec3& m : markersMeters) {
    const int mc =
        static_cast<int>(std::floor((m.x - picture.minMeters.x) / picture.metersPerPixel));
    const int mr =
        picture.height - 1 -
        static_cast<int>(std::floor((m.y - picture.minMeters.y) / picture.metersPerPixel));
    for (int dr = -3; dr <= 3; ++dr) {
      for (int dc = -3; dc <= 3; ++dc) {
        const int col = mc + dc, row = mr + dr;
        if (col < 0 || row < 0 || col >= picture.width || row >= picture.height) continue;
        const std::uint8_t v = (std::abs(dr) <= 1 && std::abs(dc) <= 1) ? 0 : 255;
        const std::size_t i = (static_cast<std::size_t>(row) * picture.width + col) * 3;
        picture.rgb8[i] = picture.rgb8[i + 1] = picture.rgb8[i + 2] = v;
      }
    }
  }
  return picture;
}

}  // namespace probeproxy
