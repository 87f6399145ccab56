#pragma once
// Comma-separated numbers on the command line (`--camera 1,2,1.7`), checked strictly: exactly
// `count` finite decimal numbers, nothing else, so a typo is one clear line and exit 2.

#include <cstddef>
#include <string_view>
#include <vector>

namespace probeproxy::cli {

// Throws InputError(option, "expected N comma-separated numbers, got '<text>'").
std::vector<double> parseNumberList(std::string_view text, std::size_t count,
                                    std::string_view option);

}  // namespace probeproxy::cli
