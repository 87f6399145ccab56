#include "geometry/layout/engine_presets.h"

#include "geometry/engines/engine_model.h"
#include "geometry/layout/engine_preset_options.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/open_space.h"
#include "geometry/survey/capture_sights.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <string>
#include <tuple>
#include <variant>

namespace probeproxy {

namespace {

// Floor that does not get the reflection right: over the tolerance, the fallback's share, or
// shown by probes that cannot see what it reflects (engine_preset_options.cpp, badArea).
double badFloorShare(const SurveyFigures& f) {
  return f.overToleranceShare + f.uncoveredShare + f.occludedShare;
}

bool better(const SurveyFigures& a, const SurveyFigures& b) {
  const double pa = std::isnan(a.p95Deg) ? INFINITY : a.p95Deg;
  const double pb = std::isnan(b.p95Deg) ? INFINITY : b.p95Deg;
  return std::make_tuple(badFloorShare(a), pa) < std::make_tuple(badFloorShare(b), pb);
}

// The entries of `engine` in `from`, into `to` (from {}: the engine's entries removed).
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

// `engine`'s priority field in `e`, where it has one and an entry.
void setPriority(Engine engine, RuntimeEngines& e, int priority) {
  if (engine == Engine::Unity && e.unity) e.unity->importance = priority;
}

}  // namespace

std::vector<int> enginePriorities(Engine engine) {
  if (engine == Engine::Unity) return {1, 2};
  return {};
}

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

// As written to proxies.json and read back: the numbers the engine gets.
RuntimeExport asWritten(const RuntimeExport& presets) {
  return parseRuntimeExport(runtimeExportJson(presets), kProxiesJsonName);
}

// The presets each policy makes, as proxies.json will read them back (the engine numbers
// rounded as written), made once however many engines try the policy.
class PresetsByPolicy {
 public:
  PresetsByPolicy(const Scene& scene, const std::vector<ProbeProxyBuild>& builds)
      : scene_(scene), builds_(builds) {}

  const RuntimeExport& operator()(const EnginePresetPolicy& policy) {
    for (const auto& [made, presets] : made_)
      if (made == policy) return presets;
    made_.emplace_back(policy, asWritten(makeRuntimeExport(scene_, builds_, policy)));
    return made_.back().second;
  }

  const Scene& scene() const { return scene_; }
  const std::vector<ProbeProxyBuild>& builds() const { return builds_; }

 private:
  const Scene& scene_;
  const std::vector<ProbeProxyBuild>& builds_;
  std::deque<std::pair<EnginePresetPolicy, RuntimeExport>> made_;  // stable references
};

// The build with its candidate `k` alone, kept: the export then takes that candidate's box.
ProbeProxyBuild withBoxKept(const ProbeProxyBuild& build, std::size_t k) {
  ProbeProxyBuild boxed = build;
  boxed.candidates = {build.candidates.at(k)};
  boxed.kept = 0;
  return boxed;
}

// The export of the engine's presets under the choice's policy, with each probe's box,
// priority and capture point as the choice says.
RuntimeExport enginePresets(const EnginePresetChoice& choice, const Scene& scene,
                            const std::vector<ProbeProxyBuild>& builds) {
  std::vector<ProbeProxyBuild> boxed = builds;
  for (std::size_t i = 0; i < choice.boxFrom.size(); ++i)
    if (choice.boxFrom[i] >= 0)
      boxed[i] = withBoxKept(builds[i], static_cast<std::size_t>(choice.boxFrom[i]));
  RuntimeExport presets = makeRuntimeExport(scene, boxed, choice.policy);
  if (std::find(choice.atBoxCentre.begin(), choice.atBoxCentre.end(), true) !=
      choice.atBoxCentre.end()) {
    EnginePresetPolicy centred = choice.policy;
    centred.eeveeAtBoxCentre = true;
    const RuntimeExport moved = makeRuntimeExport(scene, boxed, centred);
    for (std::size_t i = 0; i < presets.probes.size(); ++i)
      if (choice.atBoxCentre[i]) presets.probes[i].engines.eevee = moved.probes[i].engines.eevee;
  }
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    RuntimeEngines& e = presets.probes[i].engines;
    if (!choice.priority.empty()) setPriority(choice.engine, e, choice.priority[i]);
    if (!choice.boxFrom.empty() && choice.boxFrom[i] == kLeftOut)
      takeEngine(choice.engine, RuntimeEngines{}, e);
  }
  return presets;
}

// The name of the build candidate `engine`'s entry was made from; empty where it has none.
std::string entrySource(Engine engine, const RuntimeEngines& e) {
  const auto name = [](const auto& entry) {
    return entry ? entry->source.candidate : std::string();
  };
  switch (engine) {
    case Engine::Generic:
      return {};
    case Engine::Unity:
      return name(e.unity);
    case Engine::UnityHdrp:
      return name(e.unityHdrp);
    case Engine::Unreal:
      return name(e.unrealBox);
    case Engine::Godot3:
      return name(e.godot);
    case Engine::Godot4:
      return name(e.godot4);
    case Engine::Bevy:
      return name(e.bevy);
    case Engine::Eevee:
      return name(e.eevee);
  }
  return {};
}

// Where EEVEE may capture a probe at its box's centre: a point in the open, clear of every
// surface as a layout's capture points are, in plain sight of the probe's own capture point (the
// same air: not across a wall in a box that holds two rooms).
bool captureCanMoveTo(const LevelRayCaster& level, glm::dvec3 fromMeters, glm::dvec3 toMeters) {
  const glm::dvec3 way = toMeters - fromMeters;
  const double distance = glm::length(way);
  if (distance > 0.0) {
    const RayHit hit = level.firstHit({fromMeters, glm::vec3(way / distance)});
    if (hit.hit() && double(hit.t) < distance) return false;
  }
  return !lookUpAndDown(level, std::span(&toMeters, 1))[0].insideSolid &&
         nearestSurface(level, toMeters).distanceMeters >= kLayoutCaptureClearanceMeters;
}

// One way to make a probe's entry for the engine: from its default box or another its build
// fitted, at one of the engine's priorities, captured where the scene says or (EEVEE) at the
// box's centre.
struct EntryOption {
  int probe = 0;
  int box = kDefaultBox;
  int priority = 0;
  bool atBoxCentre = false;
};

// Each probe's box, priority and (EEVEE) capture point for `choice.engine` under
// `choice.policy`: its default box, another its build fitted, or none, at each of the engine's
// priorities, whichever the engine renders the trial floor best with
// (engine_preset_options.h). `defaults` are the policy's presets as the export makes them (each
// names its source box).
void chooseProbeEntries(EnginePresetChoice& choice, const Scene& scene,
                        const std::vector<ProbeProxyBuild>& builds, const RuntimeExport& defaults,
                        const LevelRayCaster& level, const SurveyFloor& trialFloor,
                        CaptureSights& trialSights, const SurveyOptions& options,
                        std::size_t keptProbes) {
  const Engine engine = choice.engine;
  std::vector<int> priorities = enginePriorities(engine);
  const bool prioritised = !priorities.empty();
  if (!prioritised) priorities = {0};  // one pass, nothing set
  const std::vector<bool> centrings =
      engine == Engine::Eevee ? std::vector<bool>{false, true} : std::vector<bool>{false};
  // Every option as a probe of its own: each probe's default box, then each other box, each at
  // every priority and capture point; the ones captured at their box's centre made by that
  // policy, in an export of their own.
  std::vector<EntryOption> entryOptions;
  RuntimeExport optionPresets;
  for (const bool centred : centrings) {
    Scene optionScene = scene;
    optionScene.probes.clear();
    std::vector<ProbeProxyBuild> optionBuilds;
    for (std::size_t i = 0; i < builds.size(); ++i) {
      const auto& candidates = builds[i].candidates;
      for (int k = kDefaultBox; k < static_cast<int>(candidates.size()); ++k) {
        if (k >= 0 &&
            (!std::holds_alternative<BoxShape>(candidates[static_cast<std::size_t>(k)].shape) ||
             candidateName(candidates[static_cast<std::size_t>(k)]) ==
                 entrySource(engine, defaults.probes[i].engines)))
          continue;
        for (const int priority : priorities) {
          ProbeProxyBuild option =
              k >= 0 ? withBoxKept(builds[i], static_cast<std::size_t>(k)) : builds[i];
          // Named apart: an export holds each name once.
          option.probe.append("/").append(std::to_string(k));
          option.probe.append("/").append(std::to_string(priority));
          optionScene.probes.push_back(scene.probes[i]);
          optionScene.probes.back().name = option.probe;
          optionBuilds.push_back(std::move(option));
          entryOptions.push_back({static_cast<int>(i), k, priority, centred});
        }
      }
    }
    EnginePresetPolicy policy = choice.policy;
    policy.eeveeAtBoxCentre = centred;
    RuntimeExport made = makeRuntimeExport(optionScene, optionBuilds, policy);
    for (auto& probe : made.probes) optionPresets.probes.push_back(std::move(probe));
  }
  for (std::size_t j = 0; j < optionPresets.probes.size(); ++j) {
    const EntryOption& o = entryOptions[j];
    RuntimeEngines& e = optionPresets.probes[j].engines;
    if (prioritised) setPriority(engine, e, o.priority);
    if (o.atBoxCentre && e.eevee &&
        !captureCanMoveTo(level, scene.probes[static_cast<std::size_t>(o.probe)].captureMeters,
                          e.eevee->location))
      e.eevee.reset();
  }
  const EngineModel model = engineModel(engine, optionPresets, options.blend);
  // The model holds the options with an entry for the engine; each names its probe and how it
  // is made.
  std::vector<int> probeOf, start(builds.size(), -1);
  for (std::size_t j = 0; j < model.probes.size(); ++j) {
    const EntryOption& o = entryOptions[static_cast<std::size_t>(model.probes[j].sceneProbe)];
    probeOf.push_back(o.probe);
    if (o.box == kDefaultBox && o.priority == priorities.front() && !o.atBoxCentre)
      start[static_cast<std::size_t>(o.probe)] = static_cast<int>(j);
  }
  const std::vector<int> chosen = chooseEngineOptions(
      model, probeOf, start, trialFloor, level, options.toleranceDeg, keptProbes, &trialSights);
  choice.boxFrom.assign(builds.size(), kDefaultBox);
  if (prioritised) choice.priority.assign(builds.size(), priorities.front());
  choice.atBoxCentre.assign(builds.size(), false);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (chosen[i] == start[i]) continue;
    if (chosen[i] < 0) {
      choice.boxFrom[i] = kLeftOut;
      continue;
    }
    const EntryOption& o = entryOptions[static_cast<std::size_t>(
        model.probes[static_cast<std::size_t>(chosen[i])].sceneProbe)];
    choice.boxFrom[i] = o.box;
    if (prioritised) choice.priority[i] = o.priority;
    choice.atBoxCentre[i] = o.atBoxCentre;
  }
}

// Whether two policies make the same boxes and influences, told apart only by their fades: the
// probes' entries, chosen next, leave out or change boxes, which the fades do not decide.
bool sameBoxes(const EnginePresetPolicy& a, const EnginePresetPolicy& b) {
  return a.clipToInfluence == b.clipToInfluence && a.cubeAboutCapture == b.cubeAboutCapture &&
         a.influenceInside == b.influenceInside && a.eeveeAtBoxCentre == b.eeveeAtBoxCentre;
}

// `engine`'s presets as `choice` makes them, read back as written.
RuntimeExport chosenPresets(const EnginePresetChoice& choice, PresetsByPolicy& presetsOf,
                            ProbeEntries entries) {
  return entries.choose ? asWritten(enginePresets(choice, presetsOf.scene(), presetsOf.builds()))
                        : presetsOf(choice.policy);
}

// The policy `engine` (not Generic) renders the trial floor best with, each probe's entry
// under it as `entries` says, and the kept presets surveyed on `floor`. Before the entries the
// trial floor is mostly not right for reasons the entries remove (probes that cannot see what
// they show, left out next), so the policies are first ranked within each kind of box, then the
// best of each kind gets its entries and the finished ones are compared.
EnginePresetChoice choose(Engine engine, PresetsByPolicy& presetsOf, const LevelRayCaster& level,
                          const SurveyFloor& floor, const SurveyFloor& trialFloor,
                          CaptureSights& trialSights, const SurveyOptions& survey,
                          std::span<const EnginePresetPolicy> policies, ProbeEntries entries) {
  SurveyOptions options = survey;
  options.engine = engine;
  const auto onTrialFloor = [&](const RuntimeExport& presets) {
    return surveyModel(engineModel(engine, presets, options.blend), trialFloor, level, options,
                       &trialSights)
        .figures;
  };
  std::vector<EnginePresetTrial> trials;
  std::vector<std::size_t> bestOfKind;  // index into `trials`, one per kind of box
  for (const EnginePresetPolicy& policy : policies) {
    trials.push_back({policy, onTrialFloor(presetsOf(policy)), std::nullopt});
    const auto kind = std::find_if(bestOfKind.begin(), bestOfKind.end(), [&](std::size_t k) {
      return sameBoxes(trials[k].policy, policy);
    });
    if (kind == bestOfKind.end())
      bestOfKind.push_back(trials.size() - 1);
    else if (better(trials.back().figures, trials[*kind].figures))
      *kind = trials.size() - 1;
  }
  EnginePresetChoice best;
  std::optional<SurveyFigures> bestFinished;
  for (const std::size_t k : bestOfKind) {
    EnginePresetChoice finished;
    finished.engine = engine;
    finished.policy = trials[k].policy;
    if (entries.choose) {
      chooseProbeEntries(finished, presetsOf.scene(), presetsOf.builds(),
                         presetsOf(finished.policy), level, trialFloor, trialSights, options,
                         entries.keptProbes);
      trials[k].finished = onTrialFloor(chosenPresets(finished, presetsOf, entries));
    }
    const SurveyFigures judged = trials[k].finished.value_or(trials[k].figures);
    if (!bestFinished || better(judged, *bestFinished)) {
      bestFinished = judged;
      best = std::move(finished);
    }
  }
  best.trials = std::move(trials);
  best.survey =
      surveyModel(engineModel(engine, chosenPresets(best, presetsOf, entries), options.blend),
                  floor, level, options);
  return best;
}

}  // namespace

std::vector<EnginePresetChoice> choosePresetsForEngines(
    std::span<const Engine> engines, const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
    const LevelRayCaster& level, const SurveyFloor& floor, const SurveyFloor& trialFloor,
    const SurveyOptions& survey, ProbeEntries entries,
    const std::function<void(Engine)>& onEngineDone) {
  PresetsByPolicy presetsOf(scene, builds);  // most policies are tried by every engine
  // Every engine's trials and option searches look from the same capture points at the same
  // trial floor: each ray is cast once for all of them.
  CaptureSights trialSights(trialFloor);
  std::vector<EnginePresetChoice> choices;
  for (const Engine engine : engines) {
    if (engine == Engine::Generic) continue;
    choices.push_back(choose(engine, presetsOf, level, floor, trialFloor, trialSights, survey,
                             enginePresetPolicies(engine), entries));
    if (onEngineDone) onEngineDone(engine);
  }
  return choices;
}

RuntimeExport exportForEngines(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                               std::span<const EnginePresetChoice> choices) {
  RuntimeExport merged = makeRuntimeExport(scene, builds);
  for (const EnginePresetChoice& choice : choices) {
    const RuntimeExport own = enginePresets(choice, scene, builds);
    for (std::size_t i = 0; i < merged.probes.size(); ++i)
      takeEngine(choice.engine, own.probes[i].engines, merged.probes[i].engines);
  }
  return merged;
}

}  // namespace probeproxy
