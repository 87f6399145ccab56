#pragma once
// `layout`: the fewest probes for a whole level, their influence volumes and proxies, and what a
// player then sees (docs/layout.md); or a baseline layout (a grid, the spawn points) measured
// the same way, so layouts compare with `survey`'s figures.
//
// Path of one run: plugin/cli/verbs/layout_verb.cpp parses flags into LayoutJobOptions ->
// runLayoutJob (here) reads the level (a scene file's, or a mesh or BSP file) and seeds the
// floor at its spawn points (else the scene's capture points) -> geometry/layout: candidates,
// their coarse proxies and errors, the greedy cover, influence boxes -> geometry/probe_proxies
// builds each chosen probe's proxy -> geometry/survey measures the result -> the scene file, the
// export and the error maps are written at the end, all or nothing.

#include "core/proxy/proxy_candidate.h"
#include "core/scene/scene.h"
#include "geometry/layout/engine_presets.h"
#include "geometry/layout/layout_options.h"
#include "geometry/layout/run_layout.h"
#include "geometry/survey/survey_map.h"
#include "geometry/survey/survey_options.h"
#include "geometry/survey/survey_result.h"
#include "plugin/jobs/job_progress.h"
#include "plugin/jobs/scene_input.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace probeproxy::jobs {

struct LayoutJobOptions {
  // A scene file (its level; its probes seed the floor where the level has no spawn points), or
  // a level file (.glb, .gltf, .obj, .ply, .off, .bsp) in Z-up metres (glTF: Y-up).
  std::filesystem::path levelOrScene;
  // Or, when levelOrScene is empty, a scene handed over in memory with its level (the add-on's
  // Suggest Probes): the same layout, seeded the same way.
  SceneInput input;
  std::filesystem::path outFolder;  // layout.scene.json, proxies.json/.glb, layout.json, maps
  SurveyMapOptions maps;
  // The floor and player the user named (seeds, grid, step, head room, eyes) and the tolerance
  // (overriding layout.toleranceDeg); unset: the scene's measured_with, then the level's
  // (plugin/jobs/measure_settings.h). No seeds anywhere: the scene's capture points, else the
  // level's floor regions (floor_seed.h).
  MeasureSettings given;
  int threads = 0;  // 0: all cores
  LayoutOptions layout;
  // Whether layout.captureHeightMeters was named. With layout.keepAuthored and no height named,
  // the added probes are captured as high over their floor as the artist's are (their median).
  bool captureHeightGiven = false;
  SurveyOptions survey;  // how the result is measured (the generic model); seeds as the layout's
  // The engines the level ships to: each gets the presets it renders best and its own figures
  // (geometry/layout/engine_presets.h). With exactly one, the layout's survey is that engine's.
  std::vector<Engine> engines;
  // Where the laid-out probes' final proxies are built when not here: given each probe's packed
  // task (geometry/layout/proxy_build_wire.h), returns each one's packed build, in order
  // (scripts/layout_dask.py sends them to a Dask cluster, LayoutWorker::buildProxy answers).
  // Empty: here, all cores.
  std::function<std::vector<std::string>(const std::vector<std::string>&)> buildProxies;

  void check() const;  // throws InputError naming the option at fault
};

struct LayoutJobResult {
  Scene scene;  // the layout: its probes, level paths relative to outFolder
  LayoutResult layout;
  std::vector<ProbeProxyBuild> builds;       // scene order
  SurveyResult survey;                       // the generic model's, or the one engine's
  double toleranceDeg = 0.0;                 // the layout's, as resolved
  std::vector<EnginePresetChoice> engines;   // each engine asked for (Generic left out)
  std::vector<glm::dvec3> seedPointsMeters;  // where the floor was flood-filled from
  // "option", "scene", "spawn points", "probes" or "the level's floor regions"
  std::string seededFrom;
  std::string json;                            // layout.json: the layout's and survey's figures
  std::vector<std::filesystem::path> written;  // when outFolder is set
};

LayoutJobResult runLayoutJob(const LayoutJobOptions& options, const Progress& progress = {});

}  // namespace probeproxy::jobs
