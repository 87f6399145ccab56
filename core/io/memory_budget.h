#pragma once
// How much memory this process may take: the machine's physical memory, or less where the
// process runs under an address-space or data limit (ulimit -v, a container). A job whose
// worst case is known before it allocates (layout's candidate tables) checks against this and
// refuses with one line, instead of dying of std::bad_alloc or the out-of-memory killer
// half-way.

#include <cstdint>
#include <string>

namespace probeproxy {

std::uint64_t usableMemoryBytes();

// "3.2 GiB": bytes as a person reads them, one decimal.
std::string gibibytesText(std::uint64_t bytes);

}  // namespace probeproxy
