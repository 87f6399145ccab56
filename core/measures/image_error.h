#pragma once
// Image error (docs/methods_and_measures.md, "Measures"): a reconstructed reflection against a
// reference render of the same view, over the pixels a mask selects, in linear HDR.
//
//   MSE  = mean over masked pixels and the 3 channels of (reconstruction - reference)^2
//   PSNR = 10 log10(peak^2 / MSE) dB, peak = the reference's largest channel value over the mask
//   MAE  = mean over masked pixels and channels of |reconstruction - reference|
// A missed pixel (no lookup: the seeds' red pixel) counts as black in MSE and MAE, so a method
// cannot gain by missing; miss_rate says how many there were. The peak depends on the reference
// and the mask only, so every method compared on one view is measured against the same peak.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace probeproxy {

struct ImageErrorFigures {
  double psnrDb = std::numeric_limits<double>::quiet_NaN();        // +inf for an exact match
  double meanAbsError = std::numeric_limits<double>::quiet_NaN();  // linear radiance units
  double missRate = 0.0;                                           // missed / masked pixels
  double peak = 0.0;       // the PSNR peak: reference max over the mask
  std::size_t pixels = 0;  // masked pixels
};

// All images interleaved RGB of one size; mask and miss one byte per pixel (non-zero = set).
// Throws std::invalid_argument when the sizes differ or the mask selects nothing.
ImageErrorFigures imageError(std::span<const float> referenceRgb,
                             std::span<const float> reconstructionRgb,
                             std::span<const std::uint8_t> mask,
                             std::span<const std::uint8_t> miss);

// Per-pixel error for heatmaps: mean over the channels of |reconstruction - reference|
// (0 outside the mask; a miss counts as black).
std::vector<float> absErrorPerPixel(std::span<const float> referenceRgb,
                                    std::span<const float> reconstructionRgb,
                                    std::span<const std::uint8_t> mask,
                                    std::span<const std::uint8_t> miss);

}  // namespace probeproxy
