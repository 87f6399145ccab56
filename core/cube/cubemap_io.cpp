#include "core/cube/cubemap_io.h"

#include "core/cube/write_depth_cube.h"  // cubeFacePath
#include "core/errors/input_error.h"
#include "core/image/write_exr.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

namespace probeproxy {

namespace {

float linearFromSrgb(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

std::string sizeText(int width, int height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

// One face as interleaved linear RGB; sets faceSize to its (square) size.
std::vector<float> readFace(const std::filesystem::path& file, int& faceSize) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(file, "cube face file is missing");
  }
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string());
  if (!in) throw InputError(file, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width != spec.height || spec.width < 1) {
    throw InputError(file,
                     "cube face is " + sizeText(spec.width, spec.height) + " texels, not square");
  }
  if (spec.depth > 1) throw InputError(file, "cube face is a volume image, not a 2D image");
  if (spec.nchannels != 1 && spec.nchannels < 3) {
    throw InputError(file, "cube face has " + std::to_string(spec.nchannels) +
                               " channels, expected RGB (3 or more) or grey (1)");
  }
  const int n = spec.width;
  const int channels = spec.nchannels == 1 ? 1 : 3;
  std::vector<float> read(static_cast<std::size_t>(n) * n * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, read.data())) {
    throw InputError(file, "cannot read image: " + in->geterror());
  }
  const bool srgb = !spec.format.is_floating_point() &&
                    OIIO::Strutil::iequals(spec.get_string_attribute("oiio:ColorSpace"), "sRGB");
  std::vector<float> rgb(static_cast<std::size_t>(n) * n * 3);
  for (std::size_t i = 0; i < static_cast<std::size_t>(n) * n; ++i) {
    for (int k = 0; k < 3; ++k) {
      float value = read[i * channels + (channels == 1 ? 0 : k)];
      if (srgb) value = linearFromSrgb(value);
      if (!std::isfinite(value)) {
        throw InputError(file, "cube face holds a NaN or infinite texel at (" +
                                   std::to_string(i % n) + ", " + std::to_string(i / n) + ")");
      }
      rgb[i * 3 + k] = value;
    }
  }
  faceSize = n;
  return rgb;
}

}  // namespace

Cubemap readCubemap(const std::string& pattern) {
  if (pattern.find("{face}") == std::string::npos) {
    throw InputError(pattern, "cubemap file pattern lacks {face} (e.g. probe_{face}.exr)");
  }
  std::array<std::vector<float>, kCubeFaceCount> faces;
  int size0 = 0;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const std::filesystem::path file = cubeFacePath(pattern, CubeFace(f));
    int size = 0;
    faces[f] = readFace(file, size);
    if (f == 0) {
      size0 = size;
    } else if (size != size0) {
      throw InputError(file, "cube face is " + sizeText(size, size) + " texels but face px is " +
                                 sizeText(size0, size0));
    }
  }
  Cubemap cube = Cubemap::fromFaces(size0, std::move(faces));
  cube.buildMipChain();
  return cube;
}

void writeCubemap(const Cubemap& cube, const std::string& pattern, int level) {
  if (level < 0 || level >= cube.numLevels()) {
    throw std::out_of_range("writeCubemap: level " + std::to_string(level) + " of " +
                            std::to_string(cube.numLevels()));
  }
  const CubemapLevel& l = cube.levels[static_cast<std::size_t>(level)];
  for (int f = 0; f < kCubeFaceCount; ++f) {
    writeExr(cubeFacePath(pattern, CubeFace(f)), l.faceSize, l.faceSize, {"R", "G", "B"}, l.rgb[f]);
  }
}

}  // namespace probeproxy
