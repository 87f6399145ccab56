#include "core/image/write_exr.h"

#include "core/image/image_codec.h"

#include <stdexcept>

namespace probeproxy {

void writeExr(const std::filesystem::path& file, int width, int height,
              const std::vector<std::string>& channelNames, std::span<const float> pixels) {
  if (pixels.size() != static_cast<std::size_t>(width) * height * channelNames.size()) {
    throw std::invalid_argument("writeExr: pixel count does not match the image size");
  }
  writeImageAtomically(file, "exr", width, height, channelNames, true, pixels.data());
}

}  // namespace probeproxy
