#include "core/blend/mix_cubemaps.h"

#include <stdexcept>
#include <string>

namespace probeproxy {

bool sameCubemapLayout(const Cubemap& a, const Cubemap& b) {
  return a.numLevels() == b.numLevels() && a.numLevels() > 0 && a.faceSize() == b.faceSize();
}

namespace {

// out += weight * in over n floats; kept apart so the compiler vectorizes the plain loop.
void addScaled(float* __restrict out, const float* __restrict in, float weight, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] += weight * in[i];
}

std::string sizeOf(const Cubemap& c) {
  std::string s = std::to_string(c.faceSize());
  s += " px, ";
  s += std::to_string(c.numLevels());
  s += " levels";
  return s;
}

}  // namespace

void mixCubemapsInto(std::span<const WeightedCubemap> cubes, Cubemap& mixed) {
  if (cubes.empty()) throw std::invalid_argument("mixCubemaps: no cubemap to mix");
  for (const WeightedCubemap& c : cubes) {
    if (c.cube == nullptr || c.cube == &mixed) {
      throw std::invalid_argument("mixCubemaps: null cubemap, or the output among the inputs");
    }
    if (!sameCubemapLayout(*c.cube, *cubes.front().cube)) {
      std::string problem = "mixCubemaps: cubemaps differ in size (";
      problem += sizeOf(*c.cube);
      problem += " against ";
      problem += sizeOf(*cubes.front().cube);
      problem += ")";
      throw std::invalid_argument(problem);
    }
  }
  const Cubemap& first = *cubes.front().cube;
  mixed.levels.resize(first.levels.size());
  for (std::size_t level = 0; level < mixed.levels.size(); ++level) {
    CubemapLevel& out = mixed.levels[level];
    out.faceSize = first.levels[level].faceSize;
    for (int face = 0; face < kCubeFaceCount; ++face) {
      std::vector<float>& texels = out.rgb[face];
      texels.resize(first.levels[level].rgb[face].size());
      // The first cube scales into the output, so it needs no clearing pass.
      const float* in = first.levels[level].rgb[face].data();
      const float w = cubes.front().weight;
      for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = w * in[i];
      for (const WeightedCubemap& c : cubes.subspan(1)) {
        addScaled(texels.data(), c.cube->levels[level].rgb[face].data(), c.weight, texels.size());
      }
    }
  }
}

Cubemap mixCubemaps(std::span<const WeightedCubemap> cubes) {
  Cubemap mixed;
  mixCubemapsInto(cubes, mixed);
  return mixed;
}

}  // namespace probeproxy
