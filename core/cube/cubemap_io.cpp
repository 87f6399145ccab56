#include "core/cube/cubemap_io.h"

#include "core/cube/cube_cross.h"
#include "core/cube/equirect.h"
#include "core/cube/write_depth_cube.h"  // cubeFacePath
#include "core/errors/input_error.h"
#include "core/image/rgb_image.h"
#include "core/image/write_exr.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace probeproxy {

namespace {

std::string sizeText(int width, int height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

// One face as interleaved linear RGB; sets faceSize to its (square) size.
std::vector<float> readFace(const std::filesystem::path& file, int& faceSize) {
  RgbImage face = readRgbImage(file, "cube face", SrgbImages::ToLinear);
  if (face.width != face.height || face.width < 1) {
    throw InputError(file,
                     "cube face is " + sizeText(face.width, face.height) + " texels, not square");
  }
  faceSize = face.width;
  return std::move(face.rgb);
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

Cubemap readCubemapImage(const std::filesystem::path& path) {
  if (path.string().find("{face}") != std::string::npos) return readCubemap(path.string());
  const RgbImage image = readRgbImage(path, "cubemap image", SrgbImages::ToLinear);
  const long long w = image.width, h = image.height;
  Cubemap cube;
  if (w * 3 == h * 4 && w % 4 == 0 && w > 0) {
    cube = cubeFromCross(image, CrossLayout::Horizontal);
  } else if (w * 4 == h * 3 && w % 3 == 0 && w > 0) {
    cube = cubeFromCross(image, CrossLayout::Vertical);
  } else if (w == 2 * h && w >= 4) {
    cube = cubeFromEquirect(image, image.width / 4);
  } else {
    throw InputError(path, "cubemap image is " + sizeText(image.width, image.height) +
                               " pixels: expected a 4:3 horizontal cross or a 3:4 vertical "
                               "cross of square faces, or a 2:1 equirectangular image");
  }
  cube.buildMipChain();
  return cube;
}

void writeCubemapImage(const Cubemap& cube, const std::filesystem::path& file,
                       CubemapImageLayout layout, int level) {
  switch (layout) {
    case CubemapImageLayout::HorizontalCross:
      return writeRgbExr(file, crossFromCube(cube, CrossLayout::Horizontal, level));
    case CubemapImageLayout::VerticalCross:
      return writeRgbExr(file, crossFromCube(cube, CrossLayout::Vertical, level));
    case CubemapImageLayout::Equirect:
      return writeRgbExr(file, equirectFromCube(cube, 4 * cube.faceSize(level), level));
  }
}

}  // namespace probeproxy
