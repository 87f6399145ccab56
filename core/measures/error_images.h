#pragma once
// Pictures of an image error a person can open (PNG, 8-bit sRGB-agnostic colours, written
// atomically). Mask and miss: one byte per pixel, row 0 at the top, non-zero = set.

#include <cstdint>
#include <filesystem>
#include <span>

namespace probeproxy {

// A reconstruction beside its reference, for a person to read: three panels (the reference,
// the reconstruction, |error| per pixel) each enlarged by a whole factor to at least 256
// pixels on its shorter side, titled, and a legend of the error scale in the images' own
// radiance units. Reference and reconstruction share one exposure (`peak`, e.g. the
// reference's largest channel over the mask, maps to white; sRGB-encoded). The error scale:
//   0 black -> scaleMax / 3 red -> 2 scaleMax / 3 yellow -> scaleMax and above white,
// linear between those stops; pixels outside the mask dark grey (40, 40, 40); misses cyan.
// Pass one scaleMax (e.g. a quarter of the view's PSNR peak) to every method of a view so
// their pictures compare by eye.
struct ErrorComparison {
  int width = 0, height = 0;
  std::span<const float> referenceRgb, reconstructionRgb;  // linear RGB, 3 floats a pixel
  std::span<const float> absError;                         // absErrorPerPixel
  std::span<const std::uint8_t> mask, miss;
  float peak = 1.0f, scaleMax = 1.0f;
};
void writeErrorComparisonPng(const std::filesystem::path& file, const ErrorComparison& images);

// Misses pure red (255, 0, 0), the other masked pixels white, the rest black.
void writeMissMaskPng(const std::filesystem::path& file, int width, int height,
                      std::span<const std::uint8_t> mask, std::span<const std::uint8_t> miss);

}  // namespace probeproxy
