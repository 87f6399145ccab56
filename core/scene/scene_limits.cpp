#include "core/scene/scene_limits.h"

#include <atomic>

namespace probeproxy {

namespace {
// Set once before any reading starts; atomics keep a reader on a worker thread well defined.
std::atomic<std::size_t> maxTriangles{InputLimits{}.maxTriangles};
std::atomic<std::uint64_t> maxFileBytes{InputLimits{}.maxFileBytes};

std::uint64_t mebibytesCeil(std::uint64_t bytes) { return bytes / (1u << 20) + (bytes % (1u << 20) != 0); }
}  // namespace

InputLimits inputLimits() { return {maxTriangles.load(), maxFileBytes.load()}; }

void setInputLimits(const InputLimits& limits) {
  maxTriangles = limits.maxTriangles;
  maxFileBytes = limits.maxFileBytes;
}

std::string triangleLimitProblem(std::uint64_t triangles) {
  return "the level holds " + std::to_string(triangles) + " triangles, over the limit of " +
         std::to_string(inputLimits().maxTriangles) + " (raise it with --max-triangles)";
}

std::string fileLimitProblem(const std::string& what, std::uint64_t bytes) {
  return what + " is " + std::to_string(mebibytesCeil(bytes)) + " MiB, over the limit of " +
         std::to_string(mebibytesCeil(inputLimits().maxFileBytes)) +
         " MiB (raise it with --max-file-mb)";
}

}  // namespace probeproxy
