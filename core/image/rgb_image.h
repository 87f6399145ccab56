#pragma once
// A linear float RGB image read with OpenImageIO: a Cycles render, a world-position render.
// Owns its pixels.

#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace probeproxy {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // (row * width + col) * 3 + channel, row 0 at the top, linear

  glm::vec3 at(int col, int row) const {
    const std::size_t i = (static_cast<std::size_t>(row) * width + col) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

// The first three channels of any image OpenImageIO reads (one channel: grey), as float, taken
// as linear (EXR and HDR are). Throws InputError naming the file when it is missing,
// unreadable, a volume, has two channels, or holds a NaN or infinite value.
RgbImage readRgbImage(const std::filesystem::path& file);

}  // namespace probeproxy
