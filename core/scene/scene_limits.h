#pragma once
// The numbers a scene may hold (docs/cli_and_formats.md "Limits and readers"). They are
// checked where the scene and its level are read, so that nothing past the readers meets a
// number Embree, the weight grids or an allocation cannot take.

#include <cstddef>
#include <cstdint>
#include <string>

namespace probeproxy {

// Every position (probe, influence, level vertex) within this distance of the origin on each
// axis, every half-extent and radius at most this, in metres after meters_per_unit. 100 km is
// far past any game level, and float positions there still resolve about 8 mm.
inline constexpr double kMaxSceneMeters = 1e5;
inline constexpr double kMinMetersPerUnit = 1e-6;
inline constexpr double kMaxMetersPerUnit = 1e6;

// The sizes a level may reach: checked before the memory they imply is taken, so that a
// level too big for the machine, a lying header or an archive that inflates to gigabytes
// stops with one line naming the limit instead of an out-of-memory kill. The CLI's
// --max-triangles and --max-file-mb raise them. The defaults come from measured peaks
// (docs/cli_and_formats.md): `build` holds about 150 bytes per level triangle at its peak
// (0.81 GB at 5 million, 2.9 GB at 20 million), so 50 million stay near 7 GiB, where the
// largest Quake 3 maps hold about 10^5; a 1 GiB binary PLY holds about 55 million.
struct InputLimits {
  std::uint64_t maxTriangles = 50'000'000;  // over the whole level, sky included
  // One level file on disk, a glTF's declared buffers, one .pk3 entry inflated, one image
  // decoded; in MiB as the option spells it.
  std::uint64_t maxFileMebibytes = 1024;

  std::uint64_t maxFileBytes() const { return maxFileMebibytes << 20; }
  // Throws InputError ("option max_triangles: 0 is not positive", "option max_file_mb: ... is
  // outside [1, 1048576]") as every option of the library is refused (option_checks.h).
  void check() const;
};

// The limits every reader checks. Process-wide: front ends set them once, before reading;
// setInputLimits checks them first.
InputLimits inputLimits();
void setInputLimits(const InputLimits& limits);

// "the level holds 25000000 triangles, over the limit of 20000000 (raise it with
// --max-triangles)": the error line of each limit.
std::string triangleLimitProblem(std::uint64_t triangles);
// `what` is e.g. "mesh file" or "\"maps/x.bsp\" inflated": "<what> is 3000 MiB, over the limit
// of 1024 MiB (raise it with --max-file-mb)".
std::string fileLimitProblem(const std::string& what, std::uint64_t bytes);

}  // namespace probeproxy
