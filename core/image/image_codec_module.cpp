// The image codec module (core/image/image_codec.h): every use of OpenImageIO, built as a
// shared module of its own so that OpenImageIO's libraries load only with it.

#include "core/image/image_codec.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <memory>
#include <stdexcept>

namespace probeproxy {

namespace {

void readImage(const std::filesystem::path& file,
               const std::function<PixelDestination(const ImageHeader&)>& destination) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error(OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const ImageHeader header{
      spec.width,
      spec.height,
      spec.depth,
      spec.nchannels,
      spec.format.is_floating_point(),
      OIIO::Strutil::iequals(spec.get_string_attribute("oiio:ColorSpace"), "sRGB")};
  const PixelDestination to = destination(header);
  if (!in->read_image(0, 0, 0, to.channels, OIIO::TypeDesc::FLOAT, to.pixels)) {
    throw std::runtime_error(in->geterror());
  }
}

void writeImage(const std::filesystem::path& file, const std::string& format, int width, int height,
                const std::vector<std::string>& channelNames, bool floating, const void* pixels) {
  const OIIO::TypeDesc type = floating ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(width, height, static_cast<int>(channelNames.size()), type);
  spec.channelnames = channelNames;
  if (format == "exr") {
    spec.attribute("compression", "zip");
    // Same input, same bytes: OpenImageIO stamps EXRs with the time of writing unless told a
    // fixed one, which then goes into the header as capDate.
    spec.attribute("DateTime", "2000:01:01 00:00:00");
  }
  // By format, not by the file's name: an atomic writer's temporary name ends otherwise.
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(format);
  if (!out) throw std::runtime_error(OIIO::geterror());
  if (!out->open(file.string(), spec) || !out->write_image(type, pixels) || !out->close()) {
    throw std::runtime_error(out->geterror());
  }
}

constexpr ImageCodec kCodec{readImage, writeImage};

}  // namespace

}  // namespace probeproxy

extern "C" const probeproxy::ImageCodec* probeproxy_image_codec() { return &probeproxy::kCodec; }
