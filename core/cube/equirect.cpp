#include "core/cube/equirect.h"

#include "core/cube/cubemap_sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace probeproxy {

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 pixel(const RgbImage& image, int col, int row) {
  const std::size_t at = (static_cast<std::size_t>(row) * image.width + col) * 3;
  return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

glm::vec3 sampleEquirect(const RgbImage& image, glm::vec3 d) {
  const double phi = std::atan2(static_cast<double>(d.y), static_cast<double>(d.x));
  const double theta = std::atan2(static_cast<double>(d.z), std::hypot(d.x, d.y));
  // Continuous pixel coordinates: pixel (c, r) has its centre at (c, r).
  const double x = (0.5 - phi / (2.0 * kPi)) * image.width - 0.5;
  const double y = std::clamp((0.5 - theta / kPi) * image.height - 0.5, 0.0,
                              static_cast<double>(image.height - 1));
  const double x0 = std::floor(x), y0 = std::floor(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const int w = image.width;
  const int c0 = ((static_cast<int>(x0) % w) + w) % w, c1 = (c0 + 1) % w;
  const int r0 = static_cast<int>(y0), r1 = std::min(r0 + 1, image.height - 1);
  return (1.0f - fy) * ((1.0f - fx) * pixel(image, c0, r0) + fx * pixel(image, c1, r0)) +
         fy * ((1.0f - fx) * pixel(image, c0, r1) + fx * pixel(image, c1, r1));
}

}  // namespace

glm::vec3 equirectDirection(float u, float v) {
  const double phi = (0.5 - u) * 2.0 * kPi;
  const double theta = (0.5 - v) * kPi;
  return glm::vec3(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi),
                   std::sin(theta));
}

Cubemap cubeFromEquirect(const RgbImage& image, int faceSize) {
  if (faceSize < 1) throw std::invalid_argument("cubeFromEquirect: faceSize must be at least 1");
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw std::invalid_argument("cubeFromEquirect: empty or wrongly sized image");
  }
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < faceSize; ++row) {
      for (int col = 0; col < faceSize; ++col) {
        const glm::vec3 v = sampleEquirect(image, texelDirection(CubeFace(f), col, row, faceSize));
        faces[f].insert(faces[f].end(), {v.r, v.g, v.b});
      }
    }
  }
  return Cubemap::fromFaces(faceSize, std::move(faces));
}

RgbImage equirectFromCube(const Cubemap& cube, int width, int level) {
  if (width < 2 || width % 2 != 0) {
    throw std::invalid_argument("equirectFromCube: width must be even and at least 2");
  }
  cube.levels.at(static_cast<std::size_t>(level));
  RgbImage image{width, width / 2, {}};
  image.rgb.reserve(static_cast<std::size_t>(width) * image.height * 3);
  for (int row = 0; row < image.height; ++row) {
    for (int col = 0; col < width; ++col) {
      const glm::vec3 d = equirectDirection((col + 0.5f) / static_cast<float>(width),
                                            (row + 0.5f) / static_cast<float>(image.height));
      const glm::vec3 v = sampleBilinear(cube, d, static_cast<float>(level));
      image.rgb.insert(image.rgb.end(), {v.r, v.g, v.b});
    }
  }
  return image;
}

}  // namespace probeproxy
