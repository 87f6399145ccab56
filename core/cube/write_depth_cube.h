#pragma once
// A depth cube as six single-channel EXR files (channel "Z", metres; +inf where no surface).

#include "core/cube/depth_cube.h"

#include <filesystem>
#include <string>

namespace probeproxy {

// `pattern` holds `{face}`, e.g. "depth/corridor_a_{face}.exr".
std::filesystem::path cubeFacePath(const std::string& pattern, CubeFace face);

void writeDepthCube(const DepthCube& cube, const std::string& pattern);

}  // namespace probeproxy
