#pragma once
// A linear float RGB image read with OpenImageIO: a Cycles render, a world-position render,
// a cubemap image. Owns its pixels.

#include <filesystem>
#include <string>
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

// What to do with 8/16-bit images that OpenImageIO reports in sRGB (PNG, JPEG): keep the
// stored values (a mask or heatmap probeproxy wrote), or decode them to linear radiance (a
// cubemap an artist painted). Float formats (EXR, HDR) are always taken as linear.
enum class SrgbImages { AsStored, ToLinear };

// The first three channels of any image OpenImageIO reads (one channel: grey), as float.
// `what` names the image in messages ("cube face": "cube face file is missing"). Throws
// InputError naming the file when it is missing, unreadable, a volume, has two channels, or
// holds a NaN or infinite value.
RgbImage readRgbImage(const std::filesystem::path& file, const std::string& what = "image",
                      SrgbImages srgb = SrgbImages::AsStored);

// The image as an RGB float EXR, atomically (core/image/write_exr.h).
void writeRgbExr(const std::filesystem::path& file, const RgbImage& image);

}  // namespace probeproxy
