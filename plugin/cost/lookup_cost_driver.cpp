// Runs N lookups of one workload (lookup_workload.h) through one path, with callgrind
// collecting only around the lookups, so `valgrind --tool=callgrind --instr-atstart=no
// --collect-atstart=no` counts the lookups' instructions and nothing of the set-up:
//   probeproxy_lookup_cost_driver WORKLOAD scalar|batched N
// instructions_per_lookup.h runs it for N and 2N and takes the difference. Without valgrind
// the macros do nothing and it just runs the lookups.
//   probeproxy_lookup_cost_driver --dumps scalar|batched N WORKLOAD...
// does the same for many workloads in one valgrind run (valgrind's start-up is most of a
// run's time): N then 2N lookups of each, each counted alone and dumped
// (CALLGRIND_DUMP_STATS), so dump 2i + 1 and 2i + 2 are workload i's N and 2N.

#include "plugin/cost/lookup_workload.h"

#include <valgrind/callgrind.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

// Lookups of one workload with callgrind collecting only around them.
void countedLookups(const probeproxy::LookupWorkload& w, bool batched,
                    probeproxy::LookupOutputs& out) {
  CALLGRIND_TOGGLE_COLLECT;
  if (batched) {
    probeproxy::runBatchedLookups(w, out);
  } else {
    probeproxy::runScalarLookups(w, out);
  }
  CALLGRIND_TOGGLE_COLLECT;
}

int runDumps(int argc, char** argv) {
  using namespace probeproxy;
  const bool batched = std::string(argv[2]) == "batched";
  const std::size_t n = std::stoul(argv[3]);
  CALLGRIND_START_INSTRUMENTATION;
  for (int i = 4; i < argc; ++i) {
    for (const std::size_t lookups : {n, 2 * n}) {
      const LookupWorkload w = makeLookupWorkload(argv[i], lookups);
      LookupOutputs out(lookups);
      countedLookups(w, batched, out);
      CALLGRIND_DUMP_STATS;
    }
  }
  CALLGRIND_STOP_INSTRUMENTATION;
  std::printf("%d workloads\n", argc - 4);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace probeproxy;
  if (argc >= 5 && std::string(argv[1]) == "--dumps" &&
      (std::string(argv[2]) == "scalar" || std::string(argv[2]) == "batched")) {
    try {
      return runDumps(argc, argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
      return 2;
    }
  }
  if (argc != 4 || (std::string(argv[2]) != "scalar" && std::string(argv[2]) != "batched")) {
    std::fprintf(stderr,
                 "usage: %s WORKLOAD scalar|batched N\n"
                 "       %s --dumps scalar|batched N WORKLOAD...\n",
                 argv[0], argv[0]);
    return 2;
  }
  try {
    const bool batched = std::string(argv[2]) == "batched";
    const std::size_t n = std::stoul(argv[3]);
    const LookupWorkload w = makeLookupWorkload(argv[1], n);
    LookupOutputs out(n);
    CALLGRIND_START_INSTRUMENTATION;
    CALLGRIND_TOGGLE_COLLECT;
    if (batched) {
      runBatchedLookups(w, out);
    } else {
      runScalarLookups(w, out);
    }
    CALLGRIND_TOGGLE_COLLECT;
    CALLGRIND_STOP_INSTRUMENTATION;
    std::size_t misses = 0;
    for (const std::uint8_t m : out.miss) misses += m;
    std::printf("%s %s %zu lookups, %zu misses\n", argv[1], argv[2], n, misses);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 2;
  }
  return 0;
}
