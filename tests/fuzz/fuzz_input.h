#pragma once
// What every fuzz target shares. A reader may refuse its input only with InputError (one line,
// exit 2 in the CLI); any other exception escapes the target and libFuzzer reports it as a
// crash, as it does a sanitizer report, a hang or an allocation past -malloc_limit_mb.

#include "core/errors/input_error.h"

#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace probeproxy::fuzz {

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The readers that take a path (Assimp, CGAL's soup readers, libzip, OpenImageIO) read the
// input from a file in a folder of this process's own, rewritten on every run.
inline std::filesystem::path scratchFile(const std::string& name) {
  static const std::filesystem::path folder = [] {
    auto dir =
        std::filesystem::temp_directory_path() / ("probeproxy_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return dir;
  }();
  return folder / name;
}

inline std::filesystem::path writeScratch(const std::string& name, std::string_view bytes) {
  const std::filesystem::path file = scratchFile(name);
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), std::streamsize(bytes.size()));
  return file;
}

// Runs `read`, accepting InputError as the reader's answer to bad input.
template <class Read>
int refusedOrRead(Read&& read) {
  try {
    read();
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace probeproxy::fuzz
