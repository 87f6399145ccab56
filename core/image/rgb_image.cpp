#include "core/image/rgb_image.h"

#include "core/errors/input_error.h"
#include "core/image/write_exr.h"
#include "core/io/regular_file.h"
#include "core/scene/scene_limits.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cmath>
#include <memory>
#include <string>

namespace probeproxy {

namespace {

float linearFromSrgb(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

constexpr int kMaxImageSide = 65536;

}  // namespace

RgbImage readRgbImage(const std::filesystem::path& file, const std::string& what, SrgbImages srgb) {
  requireRegularFile(file, what + " file");
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string());
  if (!in) throw InputError(file, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.depth > 1) throw InputError(file, what + " is a volume image, not a 2D image");
  if (spec.nchannels != 1 && spec.nchannels < 3) {
    throw InputError(file, what + " has " + std::to_string(spec.nchannels) +
                               " channels, expected RGB (3 or more) or grey (1)");
  }
  // The header's size, checked before the buffers it implies are taken (both found by
  // fuzz_cubemap_image): a few bytes of .hdr can claim a negative height, and OpenImageIO 2.4
  // converts 256 scanlines at a time whatever the height, so one line 5 million pixels wide
  // asked it for 15.7 GB. A 16K-face equirect is 65536 wide.
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide ||
      spec.height > kMaxImageSide) {
    throw InputError(file, what + " claims " + std::to_string(spec.width) + " x " +
                               std::to_string(spec.height) + " pixels, expected 1 to " +
                               std::to_string(kMaxImageSide) + " on a side");
  }
  const int channels = spec.nchannels == 1 ? 1 : 3;
  const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
  if (const std::uint64_t decoded = std::uint64_t(count) * 3 * sizeof(float);
      decoded > inputLimits().maxFileBytes()) {
    throw InputError(file, fileLimitProblem(what + " decoded", decoded));
  }
  std::vector<float> read(count * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, read.data())) {
    throw InputError(file, "cannot read image: " + in->geterror());
  }
  const bool decode = srgb == SrgbImages::ToLinear && !spec.format.is_floating_point() &&
                      OIIO::Strutil::iequals(spec.get_string_attribute("oiio:ColorSpace"), "sRGB");
  RgbImage image{spec.width, spec.height, std::vector<float>(count * 3)};
  for (std::size_t i = 0; i < count; ++i) {
    for (int k = 0; k < 3; ++k) {
      float value = read[i * channels + (channels == 1 ? 0 : k)];
      if (decode) value = linearFromSrgb(value);
      if (!std::isfinite(value)) {
        throw InputError(file, what + " holds a NaN or infinite value at pixel (" +
                                   std::to_string(i % spec.width) + ", " +
                                   std::to_string(i / spec.width) + ")");
      }
      image.rgb[i * 3 + k] = value;
    }
  }
  return image;
}

void writeRgbExr(const std::filesystem::path& file, const RgbImage& image) {
  writeExr(file, image.width, image.height, {"R", "G", "B"}, image.rgb);
}

}  // namespace probeproxy
