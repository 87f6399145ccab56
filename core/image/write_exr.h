#pragma once
// Linear float images as OpenEXR (OpenImageIO), written atomically. Pixels are interleaved
// channels, row 0 at the top.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace probeproxy {

void writeExr(const std::filesystem::path& file, int width, int height,
              const std::vector<std::string>& channelNames, std::span<const float> pixels);

}  // namespace probeproxy
