#include "plugin/jobs/survey/survey_job.h"

#include "core/io/atomic_write.h"
#include "core/io/output_folder.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/run_survey.h"
#include "geometry/survey/survey_map.h"
#include "plugin/jobs/measure_settings.h"
#include "plugin/jobs/survey/survey_report.h"
#include "plugin/jobs/thread_limit.h"

namespace probeproxy::jobs {

void SurveyJobOptions::check() const {
  checkAsGiven(survey, given);
  if (!outFolder.empty()) checkOutputFolder(outFolder);
}

SurveyJobResult runSurveyJob(const SurveyJobOptions& o, const Progress& progress) {
  o.check();  // before the level loads: a bad option is one line, at once
  const ThreadLimit threads(o.threads);
  const Scene scene = readSceneInput(o.input);
  const LevelMesh level = loadSceneLevel(scene, o.input);
  const LevelRayCaster rayCaster(level);
  // The floor a player walks is what the player can reach from where the level starts them;
  // a level without spawn points (an OBJ room) is entered at its probes.
  SurveyOptions survey = o.survey;
  applyMeasureSettings(resolvedMeasureSettings(o.given, scene, level), survey);
  checkWithSceneSettings(scene, [&] { survey.check(); });

  SurveyJobResult r;
  r.result = runSurvey(scene, rayCaster, survey, progress);
  r.probes = scene.probes;
  r.json = surveyReportJson(r.result, r.probes);
  if (!o.outFolder.empty()) {
    r.written.push_back(o.outFolder / "survey.json");
    writeFileAtomically(r.written.back(), r.json);
    for (const std::filesystem::path& map :
         writeSurveyMaps(r.result, scene.probes, o.outFolder, o.maps))
      r.written.push_back(map);
  }
  return r;
}

}  // namespace probeproxy::jobs
