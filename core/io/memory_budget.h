#pragma once
// How much memory this process may take: the machine's physical memory, or less where the
// process runs under an address-space or data limit (ulimit -v, a container), or the budget the
// user gives (--max-memory). A job estimates what it will need once it knows its floor, before
// it allocates the rest (survey's samples, layout's candidate tables), and refuses with one line
// instead of dying of std::bad_alloc or the out-of-memory killer half-way.

#include <cstdint>
#include <string>

namespace probeproxy {

std::uint64_t usableMemoryBytes();

// The program and its libraries (139 MB measured with OpenImageIO's 260 shared libraries, which
// load with the first picture a job writes or the first image it reads; 19 MB without).
inline constexpr std::uint64_t kProcessBytes = 160ull << 20;

// Throws InputError(what, ...) when `neededBytes` exceed the budget: `budgetBytes`, or
// usableMemoryBytes() when 0. `needs` says what the estimate is of ("the floor (...) and its
// samples"), `advice` what the user can do besides raising --max-memory.
void requireMemory(const std::string& what, std::uint64_t neededBytes, std::uint64_t budgetBytes,
                   const std::string& needs, const std::string& advice);

// "3.2 GiB": bytes as a person reads them, one decimal.
std::string gibibytesText(std::uint64_t bytes);

}  // namespace probeproxy
