#pragma once
// 8-bit RGB PNGs for people to look at (error heatmaps, miss masks), written atomically.

#include <cstdint>
#include <filesystem>
#include <span>

namespace probeproxy {

// rgb8: (row * width + col) * 3 + channel, row 0 at the top. Throws std::invalid_argument on a
// wrong length, InputError naming the file when it cannot be written.
void writePng(const std::filesystem::path& file, int width, int height,
              std::span<const std::uint8_t> rgb8);

}  // namespace probeproxy
