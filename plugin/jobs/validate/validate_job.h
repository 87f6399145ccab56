#pragma once
// `validate`: authored proxies and influence volumes checked against the level; findings with
// severity, value, limit, message and hint (geometry/validate/validate_scene.h).

#include "core/scene/measure_settings.h"
#include "geometry/validate/validate_scene.h"
#include "plugin/jobs/scene_input.h"

#include <vector>

namespace probeproxy::jobs {

struct ValidateJobOptions {
  SceneInput input;
  int threads = 0;  // 0: all cores
  ValidateOptions validate;
  // The floor the user named (seeds, grid, player); unset: the scene's measured_with, then the
  // level (plugin/jobs/measure_settings.h).
  MeasureSettings given;

  void check() const;  // throws InputError naming the option at fault
};

struct ValidateJobResult {
  std::vector<ValidationFinding> findings;
  bool fails = false;  // any error or warning: a pipeline should stop (exit 1)
};

ValidateJobResult runValidateJob(const ValidateJobOptions& options);

}  // namespace probeproxy::jobs
