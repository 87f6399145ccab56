#include "geometry/layout/engine_presets.h"

#include "geometry/engines/engine_model.h"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <tuple>

namespace probeproxy {

namespace {

// Floor that does not get the reflection right: over the tolerance, or the fallback's share.
double badFloorShare(const SurveyFigures& f) { return f.overToleranceShare + f.uncoveredShare; }

bool better(const SurveyFigures& a, const SurveyFigures& b) {
  const double pa = std::isnan(a.p95Deg) ? INFINITY : a.p95Deg;
  const double pb = std::isnan(b.p95Deg) ? INFINITY : b.p95Deg;
  return std::make_tuple(badFloorShare(a), pa) < std::make_tuple(badFloorShare(b), pb);
}

// The entries of `engine` in `from`, into `to`.
void takeEngine(Engine engine, const RuntimeEngines& from, RuntimeEngines& to) {
  switch (engine) {
    case Engine::Generic:
      break;
    case Engine::Unity:
      to.unity = from.unity;
      break;
    case Engine::UnityHdrp:
      to.unityHdrp = from.unityHdrp;
      break;
    case Engine::Unreal:
      to.unrealBox = from.unrealBox;
      to.unrealSphere = from.unrealSphere;
      break;
    case Engine::Godot3:
      to.godot = from.godot;
      break;
    case Engine::Godot4:
      to.godot4 = from.godot4;
      break;
    case Engine::Bevy:
      to.bevy = from.bevy;
      break;
    case Engine::Eevee:
      to.eevee = from.eevee;
      break;
  }
}

}  // namespace

std::vector<EnginePresetPolicy> enginePresetPolicies(Engine engine) {
  std::vector<EnginePresetPolicy> policies;
  // EEVEE fits its parallax box to the (cut) box too, so it tries both of its choices.
  const std::vector<std::pair<bool, bool>> choices =
      engine == Engine::Eevee ? std::vector<std::pair<bool, bool>>{{false, false},
                                                                   {true, false},
                                                                   {false, true},
                                                                   {true, true}}
                              : std::vector<std::pair<bool, bool>>{{false, false}, {false, true}};
  for (const auto& [clip, second] : choices) {
    // The export `build` writes; no fade (nothing to clear the floor of); wider fades, cleared.
    for (const auto& [scale, clear] : {std::pair{1.0, false}, std::pair{0.0, false},
                                       std::pair{1.0, true}, std::pair{2.0, true}}) {
      EnginePresetPolicy p;
      p.fadeScale = scale;
      p.clearTheFloor = clear;
      p.clipToInfluence = clip || (second && engine != Engine::Bevy && engine != Engine::Eevee);
      p.cubeAboutCapture = second && engine == Engine::Bevy;
      p.influenceInside = second && engine == Engine::Eevee;
      policies.push_back(p);
    }
  }
  return policies;
}

namespace {

// The presets each policy makes, as proxies.json will read them back (the engine numbers
// rounded as written), made once however many engines try the policy.
class PresetsByPolicy {
 public:
  PresetsByPolicy(const Scene& scene, const std::vector<ProbeProxyBuild>& builds)
      : scene_(scene), builds_(builds) {}

  const RuntimeExport& operator()(const EnginePresetPolicy& policy) {
    for (const auto& [made, presets] : made_)
      if (made == policy) return presets;
    made_.emplace_back(
        policy, parseRuntimeExport(runtimeExportJson(makeRuntimeExport(scene_, builds_, policy)),
                                   kProxiesJsonName));
    return made_.back().second;
  }

 private:
  const Scene& scene_;
  const std::vector<ProbeProxyBuild>& builds_;
  std::deque<std::pair<EnginePresetPolicy, RuntimeExport>> made_;  // stable references
};

EnginePresetChoice choose(Engine engine, PresetsByPolicy& presetsOf, const LevelRayCaster& level,
                          const SurveyFloor& floor, const SurveyFloor& trialFloor,
                          const SurveyOptions& survey,
                          std::span<const EnginePresetPolicy> policies) {
  if (engine == Engine::Generic)
    throw std::invalid_argument("choosePresetsForEngine: the generic model has no presets");
  SurveyOptions options = survey;
  options.engine = engine;
  EnginePresetChoice best;
  best.engine = engine;
  SurveyFigures bestTrial;
  for (const EnginePresetPolicy& policy : policies) {
    const SurveyResult trial = surveyModel(engineModel(engine, presetsOf(policy), options.blend),
                                           trialFloor, level, options);
    best.trials.push_back({policy, trial.figures});
    if (best.trials.size() == 1 || better(trial.figures, bestTrial)) {
      best.policy = policy;
      bestTrial = trial.figures;
    }
  }
  best.survey = surveyModel(engineModel(engine, presetsOf(best.policy), options.blend), floor,
                            level, options);
  return best;
}

}  // namespace

EnginePresetChoice choosePresetsForEngine(Engine engine, const Scene& scene,
                                          const std::vector<ProbeProxyBuild>& builds,
                                          const LevelRayCaster& level, const SurveyFloor& floor,
                                          const SurveyFloor& trialFloor,
                                          const SurveyOptions& survey,
                                          std::span<const EnginePresetPolicy> policies) {
  PresetsByPolicy presetsOf(scene, builds);
  return choose(engine, presetsOf, level, floor, trialFloor, survey, policies);
}

std::vector<EnginePresetChoice> choosePresetsForEngines(
    std::span<const Engine> engines, const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
    const LevelRayCaster& level, const SurveyFloor& floor, const SurveyFloor& trialFloor,
    const SurveyOptions& survey) {
  PresetsByPolicy presetsOf(scene, builds);  // most policies are tried by every engine
  std::vector<EnginePresetChoice> choices;
  for (const Engine engine : engines) {
    if (engine == Engine::Generic) continue;
    choices.push_back(
        choose(engine, presetsOf, level, floor, trialFloor, survey, enginePresetPolicies(engine)));
  }
  return choices;
}

RuntimeExport exportForEngines(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                               std::span<const EnginePresetChoice> choices) {
  RuntimeExport merged = makeRuntimeExport(scene, builds);
  for (const EnginePresetChoice& choice : choices) {
    const RuntimeExport own = makeRuntimeExport(scene, builds, choice.policy);
    for (std::size_t i = 0; i < merged.probes.size(); ++i)
      takeEngine(choice.engine, own.probes[i].engines, merged.probes[i].engines);
  }
  return merged;
}

}  // namespace probeproxy
