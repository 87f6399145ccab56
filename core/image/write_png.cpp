#include "core/image/write_png.h"

#include "core/image/image_codec.h"

#include <stdexcept>

namespace probeproxy {

void writePng(const std::filesystem::path& file, int width, int height,
              std::span<const std::uint8_t> rgb8) {
  if (width < 1 || height < 1 || rgb8.size() != static_cast<std::size_t>(width) * height * 3) {
    throw std::invalid_argument("writePng: pixel count does not match the image size");
  }
  writeImageAtomically(file, "png", width, height, {"R", "G", "B"}, false, rgb8.data());
}

}  // namespace probeproxy
