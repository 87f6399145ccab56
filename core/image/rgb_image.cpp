#include "core/image/rgb_image.h"

#include "core/errors/input_error.h"
#include "core/image/image_codec.h"
#include "core/image/write_exr.h"
#include "core/io/regular_file.h"
#include "core/scene/scene_limits.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace probeproxy {

namespace {

float linearFromSrgb(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

constexpr int kMaxImageSide = 65536;

// Grey stays one channel; of more, the first three are RGB.
int channelsKept(const ImageHeader& header) { return header.channels == 1 ? 1 : 3; }

// Refuses what the header says before any pixel is decoded.
void requireDecodable(const std::filesystem::path& file, const std::string& what,
                      const ImageHeader& header) {
  if (header.depth > 1) throw InputError(file, what + " is a volume image, not a 2D image");
  if (header.channels != 1 && header.channels < 3) {
    throw InputError(file, what + " has " + std::to_string(header.channels) +
                               " channels, expected RGB (3 or more) or grey (1)");
  }
  // The header's size, checked before the buffers it implies are taken (both found by
  // fuzz_cubemap_image): a few bytes of .hdr can claim a negative height, and OpenImageIO 2.4
  // converts 256 scanlines at a time whatever the height, so one line 5 million pixels wide
  // asked it for 15.7 GB. A 16K-face equirect is 65536 wide.
  if (header.width < 1 || header.height < 1 || header.width > kMaxImageSide ||
      header.height > kMaxImageSide) {
    throw InputError(file, what + " claims " + std::to_string(header.width) + " x " +
                               std::to_string(header.height) + " pixels, expected 1 to " +
                               std::to_string(kMaxImageSide) + " on a side");
  }
  const std::uint64_t decoded = std::uint64_t(header.width) * header.height * 3 * sizeof(float);
  if (decoded > inputLimits().maxFileBytes()) {
    throw InputError(file, fileLimitProblem(what + " decoded", decoded));
  }
}

}  // namespace

RgbImage readRgbImage(const std::filesystem::path& file, const std::string& what, SrgbImages srgb) {
  requireRegularFile(file, what + " file");
  const ImageCodec& codec = imageCodec();
  ImageHeader header;
  std::vector<float> read;
  try {
    codec.read(file, [&](const ImageHeader& found) {
      requireDecodable(file, what, found);
      header = found;
      read.resize(static_cast<std::size_t>(found.width) * found.height * channelsKept(found));
      return PixelDestination{channelsKept(found), read.data()};
    });
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& problem) {
    throw InputError(file, std::string("cannot read image: ") + problem.what());
  }
  const int channels = channelsKept(header);
  const std::size_t count = static_cast<std::size_t>(header.width) * header.height;
  const bool decode = srgb == SrgbImages::ToLinear && !header.floating && header.srgb;
  RgbImage image{header.width, header.height, std::vector<float>(count * 3)};
  for (std::size_t i = 0; i < count; ++i) {
    for (int k = 0; k < 3; ++k) {
      float value = read[i * channels + (channels == 1 ? 0 : k)];
      if (decode) value = linearFromSrgb(value);
      if (!std::isfinite(value)) {
        throw InputError(file, what + " holds a NaN or infinite value at pixel (" +
                                   std::to_string(i % header.width) + ", " +
                                   std::to_string(i / header.width) + ")");
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
