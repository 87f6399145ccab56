#include "core/scene/scene_limits.h"

#include "core/errors/option_checks.h"

#include <atomic>

namespace probeproxy {

namespace {
// Set once before any reading starts; atomics keep a reader on a worker thread well defined.
std::atomic<std::uint64_t> maxTriangles{InputLimits{}.maxTriangles};
std::atomic<std::uint64_t> maxFileMebibytes{InputLimits{}.maxFileMebibytes};

std::uint64_t mebibytesCeil(std::uint64_t bytes) {
  return bytes / (1u << 20) + (bytes % (1u << 20) != 0);
}
}  // namespace

void InputLimits::check() const {
  requirePositive("max_triangles", maxTriangles);
  // A mebibyte to a tebibyte: past that the byte count no longer fits the checks' arithmetic.
  requireInRange<std::uint64_t>("max_file_mb", maxFileMebibytes, 1, std::uint64_t(1) << 20);
}

InputLimits inputLimits() { return {maxTriangles.load(), maxFileMebibytes.load()}; }

void setInputLimits(const InputLimits& limits) {
  limits.check();
  maxTriangles = limits.maxTriangles;
  maxFileMebibytes = limits.maxFileMebibytes;
}

std::string triangleLimitProblem(std::uint64_t triangles) {
  return "the level holds " + std::to_string(triangles) + " triangles, over the limit of " +
         std::to_string(inputLimits().maxTriangles) + " (raise it with --max-triangles)";
}

std::string fileLimitProblem(const std::string& what, std::uint64_t bytes) {
  return what + " is " + std::to_string(mebibytesCeil(bytes)) + " MiB, over the limit of " +
         std::to_string(inputLimits().maxFileMebibytes) + " MiB (raise it with --max-file-mb)";
}

}  // namespace probeproxy
