#include "core/image/write_exr.h"

#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"

#include <OpenImageIO/imageio.h>

namespace probeproxy {

void writeExr(const std::filesystem::path& file, int width, int height,
              const std::vector<std::string>& channelNames, std::span<const float> pixels) {
  const int channels = static_cast<int>(channelNames.size());
  if (pixels.size() != static_cast<std::size_t>(width) * height * channels) {
    throw std::invalid_argument("writeExr: pixel count does not match the image size");
  }
  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = channelNames;
    spec.attribute("compression", "zip");
    // Same input, same bytes: OpenImageIO stamps EXRs with the time of writing unless told a
    // fixed one, which then goes into the header as capDate.
    spec.attribute("DateTime", "2000:01:01 00:00:00");
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(tmp.string());
    if (!out || !out->open(tmp.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close()) {
      throw InputError(file, "cannot write image: " + (out ? out->geterror() : OIIO::geterror()));
    }
  });
}

}  // namespace probeproxy
