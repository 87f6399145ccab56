#include "core/image/write_png.h"

#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"

#include <OpenImageIO/imageio.h>

#include <memory>
#include <stdexcept>

namespace probeproxy {

void writePng(const std::filesystem::path& file, int width, int height,
              std::span<const std::uint8_t> rgb8) {
  if (width < 1 || height < 1 || rgb8.size() != static_cast<std::size_t>(width) * height * 3) {
    throw std::invalid_argument("writePng: pixel count does not match the image size");
  }
  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    // The atomic writer's temporary name may not end in .png: name the format.
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create("png");
    if (!out || !out->open(tmp.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, rgb8.data()) || !out->close()) {
      throw InputError(file, "cannot write image: " + (out ? out->geterror() : OIIO::geterror()));
    }
  });
}

}  // namespace probeproxy
