#include "plugin/jobs/validate/validate_job.h"

#include "geometry/raycast/level_ray_caster.h"
#include "plugin/jobs/measure_settings.h"
#include "plugin/jobs/thread_limit.h"

namespace probeproxy::jobs {

void ValidateJobOptions::check() const { checkAsGiven(validate, given); }

ValidateJobResult runValidateJob(const ValidateJobOptions& o) {
  o.check();
  const ThreadLimit threads(o.threads);
  const Scene scene = readSceneInput(o.input);
  const LevelMesh level = loadSceneLevel(scene, o.input);
  const LevelRayCaster rayCaster(level);
  // The floor a player walks starts where the level starts them (as survey's and layout's).
  ValidateOptions validate = o.validate;
  applyMeasureSettings(resolvedMeasureSettings(o.given, scene, level), validate);
  checkWithSceneSettings(scene, [&] { validate.check(); });
  ValidateJobResult result;
  result.findings = validateScene(scene, rayCaster, validate);
  result.fails = findingsFail(result.findings);
  return result;
}

}  // namespace probeproxy::jobs
