// The break-point sweeps (geometry/sweeps/break_sweeps.h) as JSON on stdout, and where each
// method's p95 passes 0.1, 1 and 5 degrees on stderr:
//   build/tests/bench/break_sweeps > sweeps.json
//   /usr/bin/python3 scripts/bench_charts.py --sweeps sweeps.json OUT

#include "geometry/sweeps/break_sweeps.h"

#include <cstdio>
#include <iostream>

int main() {
  using namespace probeproxy;
  const std::vector<Sweep> sweeps = allSweeps();
  std::cout << sweepsJson(sweeps);
  for (const Sweep& s : sweeps) {
    for (const SweepSeries& m : s.series) {
      std::fprintf(stderr, "%-10s %-17s", s.name.c_str(), m.method.c_str());
      for (double limit : {0.1, 1.0, 5.0}) {
        const auto at = firstP95Above(m, limit);
        if (at)
          std::fprintf(stderr, "  p95 > %g deg from %g", limit, *at);
        else
          std::fprintf(stderr, "  p95 <= %g deg throughout", limit);
      }
      std::fprintf(stderr, "\n");
    }
  }
  return 0;
}
