#pragma once
// The options dicts of the module's functions, read into the jobs' option structs. Keys are
// the CLI's flag names in snake case (`--max-leak-share` is "max_leak_share") and the defaults
// are the CLI's; an unknown key raises ValueError here, a value out of range InputError from
// the job's own check, the same line the CLI prints.

#include "plugin/jobs/build/build_job.h"
#include "plugin/jobs/layout/layout_job.h"
#include "plugin/jobs/validate/validate_job.h"

#include <pybind11/pybind11.h>

namespace probeproxy::python {

// tolerance_deg, max_planes, max_miss_rate, face_size, samples, regenerate, threads.
void readBuildOptions(const pybind11::dict& options, jobs::BuildJobOptions& job);

// The `probeproxy validate` options: tolerance_deg, max_overlap, max_uncovered_m2,
// max_leak_share, max_inner_overlap_m3, max_weight_jump, glossy, grid, samples, rules (a list
// of rule ids); and threads.
void readValidateOptions(const pybind11::dict& options, jobs::ValidateJobOptions& job);

// The `probeproxy layout` options: tolerance_deg, max_probes, spacing, max_candidates, reach,
// capture_height, blend_band; and threads.
void readLayoutOptions(const pybind11::dict& options, jobs::LayoutJobOptions& job);

}  // namespace probeproxy::python
