// Instructions per lookup (callgrind, plugin/cost/instructions_per_lookup.h) for every row of
// bench_lookup, scalar seed port and batched kernel, as a Markdown table:
//   bench_lookup_instructions [N]        (N lookups against 2N; default 4096)
// Counts are deterministic: the same binary gives the same table.

#include "plugin/cost/instructions_per_lookup.h"

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  using namespace probeproxy;
  try {
    const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 4096;
    std::printf("| workload | scalar instructions/lookup | batched instructions/lookup |\n");
    std::printf("|---|---|---|\n");
    for (const std::string& name : costTableWorkloads()) {
      const std::optional<double> s = instructionsPerLookup(name, LookupPath::Scalar, n);
      const std::optional<double> b = instructionsPerLookup(name, LookupPath::Batched, n);
      if (!s || !b) {
        std::fprintf(stderr, "valgrind is not on PATH\n");
        return 1;
      }
      std::printf("| %s | %.1f | %.1f |\n", name.c_str(), *s, *b);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_lookup_instructions: %s\n", e.what());
    return 2;
  }
  return 0;
}
