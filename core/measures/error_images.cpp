#include "core/measures/error_images.h"

#include "core/image/write_png.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace probeproxy {

namespace {

using Rgb8 = std::array<std::uint8_t, 3>;

Rgb8 heat(float t) {
  // Stops at 0, 1/3, 2/3, 1: black, red, yellow, white.
  const float s = std::clamp(t, 0.0f, 1.0f) * 3.0f;
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return {byte(s), byte(s - 1.0f), byte(s - 2.0f)};
}

void checkSizes(int width, int height, std::size_t mask, std::size_t miss) {
  const std::size_t n = static_cast<std::size_t>(std::max(width, 0)) * std::max(height, 0);
  if (mask != n || miss != n) {
    throw std::invalid_argument("error images: mask or miss mask does not match the image size");
  }
}

}  // namespace

void writeErrorHeatmapPng(const std::filesystem::path& file, int width, int height,
                          std::span<const float> absError, std::span<const std::uint8_t> mask,
                          std::span<const std::uint8_t> miss, float scaleMax) {
  checkSizes(width, height, mask.size(), miss.size());
  if (absError.size() != mask.size() || !(scaleMax > 0.0f)) {
    throw std::invalid_argument("writeErrorHeatmapPng: wrong error size or non-positive scale");
  }
  std::vector<std::uint8_t> rgb(mask.size() * 3);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const Rgb8 c = !mask[i]  ? Rgb8{40, 40, 40}
                   : miss[i] ? Rgb8{0, 255, 255}
                             : heat(absError[i] / scaleMax);
    std::copy(c.begin(), c.end(), rgb.begin() + static_cast<std::ptrdiff_t>(i * 3));
  }
  writePng(file, width, height, rgb);
}

void writeMissMaskPng(const std::filesystem::path& file, int width, int height,
                      std::span<const std::uint8_t> mask, std::span<const std::uint8_t> miss) {
  checkSizes(width, height, mask.size(), miss.size());
  std::vector<std::uint8_t> rgb(mask.size() * 3);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const Rgb8 c = !mask[i] ? Rgb8{0, 0, 0} : miss[i] ? Rgb8{255, 0, 0} : Rgb8{255, 255, 255};
    std::copy(c.begin(), c.end(), rgb.begin() + static_cast<std::ptrdiff_t>(i * 3));
  }
  writePng(file, width, height, rgb);
}

}  // namespace probeproxy
