// Packed candidates read back (geometry/layout/candidate_wire.h): `layout` reads them from Dask
// workers and other processes, over a network; CRoaring's portable bitmaps inside.
#include "fuzz_input.h"
#include "geometry/layout/candidate_wire.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  return fuzz::refusedOrRead([&] { unpackCandidates(fuzz::asText(data, size)); });
}
