// proxies.json read back (geometry/export/runtime_export.h): engines' importers and `survey
// --proxies` feed it files that may have been edited by hand.
#include "fuzz_input.h"
#include "geometry/export/runtime_export.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  return fuzz::refusedOrRead([&] { parseRuntimeExport(fuzz::asText(data, size), "proxies.json"); });
}
