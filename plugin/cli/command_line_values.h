#pragma once
// Values typed on the command line, turned into the jobs' typed options: comma-separated
// numbers (`--camera 1,2,1.7`) checked strictly (exactly `count` finite decimal numbers,
// nothing else, so a typo is one clear line and exit 2), points, planes, method names.

#include "core/mixing/corrected_cubemap.h"
#include "core/scene/probe.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy::cli {

// Throws InputError(option, "expected N comma-separated numbers, got '<text>'").
std::vector<double> parseNumberList(std::string_view text, std::size_t count,
                                    std::string_view option);

// X,Y,Z.
glm::dvec3 parsePoint(std::string_view text, std::string_view option);

// PX,PY,PZ,NX,NY,NZ; nothing when the text is empty (the option was not given).
std::optional<ReflectionPlane> parseOptionalPlane(std::string_view text, std::string_view option);

// A memory size: a number and a unit, K, M, G or T (powers of 1024; KiB, MiB, GiB, TiB too),
// "4G", "1.5GiB", "512M"; a bare number is bytes. Throws InputError(option, ...) for anything
// else, or for zero.
std::uint64_t parseMemorySize(std::string_view text, std::string_view option);

// "mixing_plane" or "raster_convex"; throws InputError("--method", ...) otherwise.
MixingMethod parseMixingMethod(const std::string& name);

}  // namespace probeproxy::cli
