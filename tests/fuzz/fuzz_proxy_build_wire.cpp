// A probe's proxy build task and its packed build read back (geometry/layout/proxy_build_wire.h):
// `layout` sends the tasks to Dask workers and reads their builds back, over a network.
#include "fuzz_input.h"
#include "geometry/layout/proxy_build_wire.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  const std::string_view bytes = fuzz::asText(data, size);
  fuzz::refusedOrRead([&] { unpackProxyBuildTask(bytes); });
  return fuzz::refusedOrRead([&] { unpackProxyBuild(bytes); });
}
