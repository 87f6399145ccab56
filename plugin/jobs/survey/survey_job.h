#pragma once
// `survey`: what a player sees across the whole walkable floor, every probe blended as the
// runtime blends it (geometry/survey/run_survey.h): area-weighted figures, the report, and the
// error maps (one PNG per storey).
//
// Path of one run: plugin/cli/verbs/survey_verb.cpp parses flags into SurveyJobOptions ->
// runSurveyJob (here) reads the scene and level, seeds the floor at the level's spawn points ->
// geometry/survey: walkable floor by flood fill, floor samples, each probe's proxy (built by
// geometry/probe_proxies where the scene says auto), blended error per sample -> core/blend weights
// and core/parallax lookups -> figures and maps.

#include "core/scene/measure_settings.h"
#include "core/scene/scene.h"
#include "geometry/survey/survey_map.h"
#include "geometry/survey/survey_options.h"
#include "geometry/survey/survey_result.h"
#include "plugin/jobs/job_progress.h"
#include "plugin/jobs/scene_input.h"

#include <filesystem>
#include <string>
#include <vector>

namespace probeproxy::jobs {

struct SurveyJobOptions {
  SceneInput input;
  std::filesystem::path outFolder;  // survey.json and the maps; empty: nothing is written
  SurveyMapOptions maps;
  int threads = 0;  // 0: all cores
  SurveyOptions survey;
  // The floor and tolerance the user named (seeds, grid, player, tolerance_deg); what it leaves
  // unset comes from the scene's measured_with, then the level (plugin/jobs/measure_settings.h).
  // No seeds anywhere: the probes' capture points.
  MeasureSettings given;

  void check() const;  // throws InputError naming the option at fault
};

struct SurveyJobResult {
  SurveyResult result;
  std::vector<Probe> probes;                   // the scene's, which the result's indices refer to
  std::string json;                            // the `survey --json` report
  std::vector<std::filesystem::path> written;  // survey.json and the maps, when written
};

SurveyJobResult runSurveyJob(const SurveyJobOptions& options, const Progress& progress = {});

}  // namespace probeproxy::jobs
