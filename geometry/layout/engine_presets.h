#pragma once
// The presets a layout exports for the engines it ships to (`layout --engine E[,E...]`): of a
// few ways to make an engine's presets from the probes' boxes and influence volumes
// (EnginePresetPolicy: boxes cut to the influence or not, the fade's width, whether boxes reach
// below the floor), the one each engine renders best, measured by surveying each under that
// engine's model. What is measured is what is written: each trial's presets are read back
// from the proxies.json bytes they would write, and each engine's entries in the layout's
// proxies.json are its kept policy's, so `survey --engine E --proxies proxies.json` on the
// layout's scene gives the figures layout.json reports for E.

#include "core/proxy/proxy_candidate.h"
#include "core/scene/scene.h"
#include "geometry/engines/engine.h"
#include "geometry/export/runtime_export.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/run_survey.h"
#include "geometry/survey/survey_options.h"
#include "geometry/survey/survey_result.h"

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace probeproxy {

struct EnginePresetTrial {
  EnginePresetPolicy policy;
  SurveyFigures figures;  // under the engine's model, on the trial floor
  // The same with each probe's entry chosen under the policy, where it was the best of its kind
  // of box (enginePresetPolicies) and entries are chosen (ProbeEntries): finished.
  std::optional<SurveyFigures> finished;
};

// The box `build` exports for an engine: the kept proxy's, else the best of the build's boxes.
inline constexpr int kDefaultBox = -1;
inline constexpr int kLeftOut = -2;

struct EnginePresetChoice {
  Engine engine = Engine::Unity;
  EnginePresetPolicy policy;  // the one kept
  // Per scene probe, what its entry for the engine is made from (engine_preset_options.h):
  // kDefaultBox, a build candidate's index (that box), or kLeftOut (no entry: the engine
  // renders the level better without the probe). Empty: every probe kDefaultBox.
  std::vector<int> boxFrom;
  // Per scene probe, the value of the engine's priority field (enginePriorities), chosen with
  // its box. Empty: the engine's default for every probe.
  std::vector<int> priority;
  // Per scene probe, whether the engine captures it at its box's centre (EEVEE, whose one
  // transform centres both volumes on the capture point: EnginePresetPolicy::eeveeAtBoxCentre).
  // Empty: none.
  std::vector<bool> atBoxCentre;
  SurveyResult survey;                    // of its presets under the engine's model
  std::vector<EnginePresetTrial> trials;  // every policy tried, in order
};

// The values of the engine's own priority field a layout chooses among, its default first;
// empty where the engine has none. Unity's ReflectionProbe.importance: 1 (Unity's default), and
// 2 to draw a probe over every other it overlaps (a room's probe over the smaller boxes of the
// corridors reaching into it; two levels express that, more would only multiply the options).
std::vector<int> enginePriorities(Engine engine);

// The policies tried for an engine, in order: the export `build` writes (the scene's fade), no
// fade, and the fade once and twice as wide with the floor cleared; each with the engine's own
// second choice off, then on: Bevy's cube about the capture point, for the others the boxes cut
// to the influence in plan (8); EEVEE both the cut and its influence inside the scene's range in
// plan (16). Policies making the same boxes (differing only in their fades) are one kind. Of
// each kind the best on the trial floor is finished with its probes' entries (ProbeEntries), and
// of the finished ones the best is kept: the least floor over the tolerance, left to the
// engine's fallback or shown by probes that cannot see what it reflects, then the lowest p95,
// then the first.
std::vector<EnginePresetPolicy> enginePresetPolicies(Engine engine);

// Whether, after the policy, each probe's entry is chosen (its box, priority and capture point,
// or none: engine_preset_options.h). A baseline keeps every probe's default box; a layout
// chooses, but never leaves out its first `keptProbes` (the artist's probes `--keep-authored`
// kept).
struct ProbeEntries {
  bool choose = true;
  std::size_t keptProbes = 0;
};

// Every engine's choice (Generic skipped), in the order given, its policies those of
// enginePresetPolicies(). `floor` is the layout's prepared survey floor, `trialFloor` the same
// floor with fewer samples per cell, on which the policies are compared and each probe's entry
// under the kept one chosen as `entries` says; the kept presets are then surveyed on `floor` with
// the options `survey`. `onEngineDone`, when given, is told each engine as its choice is made.
std::vector<EnginePresetChoice> choosePresetsForEngines(
    std::span<const Engine> engines, const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
    const LevelRayCaster& level, const SurveyFloor& floor, const SurveyFloor& trialFloor,
    const SurveyOptions& survey, ProbeEntries entries,
    const std::function<void(Engine)>& onEngineDone = {});

// The export with each chosen engine's entries made by its kept policy (Unreal's box and
// sphere captures both by Unreal's) from the boxes it chose, every other entry by the default
// policy; no entry for an engine where it left the probe out. Each engine has entries of its own
// (Godot 3's and Godot 4's too), so no choice changes another's.
RuntimeExport exportForEngines(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                               std::span<const EnginePresetChoice> choices);

}  // namespace probeproxy
