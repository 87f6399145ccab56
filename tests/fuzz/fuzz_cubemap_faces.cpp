// Six-file cubemaps (core/cube/cubemap_io.h readCubemap). The input holds the six PNG faces
// px, nx, py, ny, pz, nz one after another, split at kFaceSeparator (also in png.dict), so
// the runs reach the checks across faces: every face square, all six the same size.
#include "core/cube/cube_face.h"
#include "core/cube/cubemap_io.h"
#include "fuzz_input.h"

#include <array>

namespace {
constexpr std::string_view kFaceSeparator = "--probeproxy-face--";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  std::string_view rest = fuzz::asText(data, size);
  for (int face = 0; face < 6; ++face) {
    const std::size_t cut = rest.find(kFaceSeparator);
    const std::string_view bytes = rest.substr(0, cut);
    rest = cut == std::string_view::npos ? std::string_view()
                                         : rest.substr(cut + kFaceSeparator.size());
    fuzz::writeScratch("face_" + std::string(cubeFaceName(CubeFace(face))) + ".png", bytes);
  }
  const std::string pattern = fuzz::scratchFile("face_{face}.png").string();
  return fuzz::refusedOrRead([&] { readCubemap(pattern); });
}
