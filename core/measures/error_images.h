#pragma once
// Pictures of an image error a person can open (PNG, 8-bit sRGB-agnostic colours, written
// atomically). Mask and miss: one byte per pixel, row 0 at the top, non-zero = set.

#include <cstdint>
#include <filesystem>
#include <span>

namespace probeproxy {

// |error| per pixel (absErrorPerPixel) on a fixed colour scale with no legend:
//   0 black -> scaleMax / 3 red -> 2 scaleMax / 3 yellow -> scaleMax and above white,
// linear between those stops; pixels outside the mask dark grey (40, 40, 40); misses cyan.
// Pass one scaleMax (e.g. a quarter of the view's PSNR peak) to every method of a view so
// their heatmaps compare by eye.
void writeErrorHeatmapPng(const std::filesystem::path& file, int width, int height,
                          std::span<const float> absError, std::span<const std::uint8_t> mask,
                          std::span<const std::uint8_t> miss, float scaleMax);

// Misses pure red (255, 0, 0), the other masked pixels white, the rest black.
void writeMissMaskPng(const std::filesystem::path& file, int width, int height,
                      std::span<const std::uint8_t> mask, std::span<const std::uint8_t> miss);

}  // namespace probeproxy
