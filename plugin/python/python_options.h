#pragma once
// The options dicts of the module's functions, read into the library's option structs. Keys
// are the CLI's flag names in snake case (`--max-leak-share` is "max_leak_share") and the
// defaults are the CLI's; an unknown key or a value the CLI would refuse raises ValueError.

#include "geometry/build/build_probe_proxy.h"
#include "geometry/validate/validate_scene.h"

#include <pybind11/pybind11.h>

namespace probeproxy::python {

// tolerance_deg, max_planes, max_miss_rate, face_size, samples, regenerate, threads.
// `threads` (0: all cores) is returned through `threads`; it is not a build option.
ProxyBuildOptions buildOptions(const pybind11::dict& options, int& threads);

// The `probeproxy validate` options: tolerance_deg, max_overlap, max_uncovered_m2,
// max_leak_share, max_inner_overlap_m3, max_weight_jump, glossy, grid, samples; and threads.
ValidateOptions validateOptions(const pybind11::dict& options, int& threads);

}  // namespace probeproxy::python
