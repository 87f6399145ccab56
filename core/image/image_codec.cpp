#include "core/image/image_codec.h"

#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace probeproxy {

namespace {

constexpr const char* kModuleName = "libprobeproxy_image_codec.so";

// Where the module may be: beside the shared object holding this code (the add-on's Python
// module, which `cmake --install` puts it beside), beside the program (the command line's
// bin/), and where the build tree made it (PROBEPROXY_IMAGE_CODEC_BUILT, core/CMakeLists.txt).
std::vector<std::filesystem::path> modulePlaces() {
  std::vector<std::filesystem::path> places;
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&modulePlaces), &self) != 0 && self.dli_fname != nullptr &&
      std::string(self.dli_fname).find('/') != std::string::npos) {
    places.push_back(std::filesystem::path(self.dli_fname).parent_path() / kModuleName);
  }
  std::error_code ec;
  if (const auto program = std::filesystem::read_symlink("/proc/self/exe", ec); !ec) {
    places.push_back(program.parent_path() / kModuleName);
  }
  places.emplace_back(PROBEPROXY_IMAGE_CODEC_BUILT);
  return places;
}

const ImageCodec& loadImageCodec() {
  std::string problems;
  for (const std::filesystem::path& path : modulePlaces()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) continue;
    // RTLD_LOCAL: OpenImageIO's libraries stay out of the program's symbol scope.
    if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      using Entry = const ImageCodec* (*)();
      if (auto entry = reinterpret_cast<Entry>(dlsym(module, "probeproxy_image_codec"))) {
        return *entry();
      }
      problems += path.string() + " has no probeproxy_image_codec; ";
    } else {
      problems += std::string(dlerror()) + "; ";
    }
  }
  throw std::runtime_error("the image codec module " + std::string(kModuleName) +
                           " (OpenImageIO) cannot be loaded: " +
                           (problems.empty() ? "not beside the program nor in the build tree"
                                             : problems.substr(0, problems.size() - 2)));
}

}  // namespace

const ImageCodec& imageCodec() {
  static const ImageCodec& codec = loadImageCodec();
  return codec;
}

void writeImageAtomically(const std::filesystem::path& file, const std::string& format, int width,
                          int height, const std::vector<std::string>& channelNames, bool floating,
                          const void* pixels) {
  const ImageCodec& codec = imageCodec();
  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    try {
      codec.write(tmp, format, width, height, channelNames, floating, pixels);
    } catch (const std::runtime_error& problem) {
      throw InputError(file, std::string("cannot write image: ") + problem.what());
    }
  });
}

}  // namespace probeproxy
