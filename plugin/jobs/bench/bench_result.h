#pragma once
// One row of `probeproxy bench`: one candidate proxy of one probe with the method that looks
// it up, its cost and its error (docs/methods_and_measures.md "Measures"). A figure not measured is
// empty, and the reports print it as null, never as a made-up number.

#include "core/measures/error_figures.h"

#include <optional>
#include <string>

namespace probeproxy::jobs {

struct BenchResult {
  std::string scene;      // the scene file's name without ".scene.json"
  std::string probe;      // the probe's name
  std::string candidate;  // how the proxy was made: "cheap_k", "aabb", "convex_12", "authored"...
  std::string
      method;      // docs/methods_and_measures.md's method id: "infinite", "cheap_k", ..., "convex"
  int planes = 0;  // planes the shader tests (0 for infinite, cheap_k, sphere)
  bool kept = false;                            // the candidate `build` keeps for this probe
  std::optional<double> nsPerLookup;            // batched kernel, median CPU ns per lookup
  std::optional<double> nsPerLookupScalar;      // scalar seed-code port, same rays, same run
  std::optional<double> instructionsPerLookup;  // callgrind, when measured
  std::optional<double> psnrDb;                 // mirror view against Cycles, when measured
  ErrorFigures error;                           // angular error on the probe's mirror_floor samples
};

}  // namespace probeproxy::jobs
