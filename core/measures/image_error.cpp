#include "core/measures/image_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace probeproxy {

namespace {

void checkSizes(std::span<const float> reference, std::span<const float> reconstruction,
                std::span<const std::uint8_t> mask, std::span<const std::uint8_t> miss) {
  if (reference.size() != reconstruction.size() || reference.size() != mask.size() * 3 ||
      miss.size() != mask.size()) {
    throw std::invalid_argument("imageError: the images, mask and miss mask differ in size");
  }
}

float reconstructed(std::span<const float> reconstruction, std::span<const std::uint8_t> miss,
                    std::size_t pixel, int channel) {
  return miss[pixel] ? 0.0f : reconstruction[pixel * 3 + channel];
}

}  // namespace

ImageErrorFigures imageError(std::span<const float> reference,
                             std::span<const float> reconstruction,
                             std::span<const std::uint8_t> mask,
                             std::span<const std::uint8_t> miss) {
  checkSizes(reference, reconstruction, mask, miss);
  ImageErrorFigures out;
  double squared = 0.0, absolute = 0.0;
  std::size_t missed = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    ++out.pixels;
    missed += miss[i] ? 1 : 0;
    for (int k = 0; k < 3; ++k) {
      const double ref = reference[i * 3 + k];
      const double e = reconstructed(reconstruction, miss, i, k) - ref;
      squared += e * e;
      absolute += std::abs(e);
      out.peak = std::max(out.peak, ref);
    }
  }
  if (out.pixels == 0) throw std::invalid_argument("imageError: the mask selects no pixel");
  const double samples = 3.0 * static_cast<double>(out.pixels);
  const double mse = squared / samples;
  out.meanAbsError = absolute / samples;
  out.missRate = static_cast<double>(missed) / static_cast<double>(out.pixels);
  out.psnrDb = mse > 0.0 ? 10.0 * std::log10(out.peak * out.peak / mse)
                         : std::numeric_limits<double>::infinity();
  return out;
}

std::vector<float> absErrorPerPixel(std::span<const float> reference,
                                    std::span<const float> reconstruction,
                                    std::span<const std::uint8_t> mask,
                                    std::span<const std::uint8_t> miss) {
  checkSizes(reference, reconstruction, mask, miss);
  std::vector<float> out(mask.size(), 0.0f);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    float sum = 0.0f;
    for (int k = 0; k < 3; ++k) {
      sum += std::abs(reconstructed(reconstruction, miss, i, k) - reference[i * 3 + k]);
    }
    out[i] = sum / 3.0f;
  }
  return out;
}

}  // namespace probeproxy
