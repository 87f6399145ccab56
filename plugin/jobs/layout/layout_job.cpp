#include "plugin/jobs/layout/layout_job.h"
#include "plugin/jobs/layout/layout_setup.h"

#include "plugin/jobs/measure_settings.h"

#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"
#include "core/io/output_folder.h"
#include "geometry/export/runtime_export.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/layout_proxy.h"
#include "geometry/layout/proxy_build_wire.h"
#include "geometry/level/write_level_mesh.h"
#include "geometry/probe_proxies/authored_proxy_shape.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/raycast/open_space.h"
#include "geometry/scene/scene_file.h"
#include "geometry/survey/run_survey.h"
#include "geometry/survey/survey_map.h"
#include "plugin/jobs/survey/survey_report.h"
#include "plugin/jobs/thread_limit.h"

#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <span>

namespace probeproxy::jobs {

namespace {

// Samples per floor cell on which an engine's preset policies are compared: a quarter of the
// survey's 8, enough to rank them (the kept one is surveyed in full).
constexpr int kEngineTrialSamplesPerCell = 2;
// And at most this many in all: a larger floor is walked on a coarser grid for the trials
// (each step doubling the spacing). An option search re-weighs a probe's samples each time a
// move near it stales it; on silvercity's open 35,000 m^2, 1.1 million samples at 0.25 m kept
// Godot 3's (every box that holds a point averaged in) running past 15 minutes. Every other
// corpus map's trial floor holds fewer (dieselpower's 373,000 the most).
constexpr double kMaxEngineTrialSamples = 400'000;

namespace fs = std::filesystem;

const char* baselineName(LayoutBaseline baseline) {
  switch (baseline) {
    case LayoutBaseline::Grid:
      return "grid";
    case LayoutBaseline::Spawn:
      return "spawn";
    case LayoutBaseline::None:
      break;
  }
  return "layout";
}

// A kept probe as layout.scene.json spells it: its files (an authored convex mesh, its
// cubemaps) reached from the new folder.
Probe keptProbe(Probe probe, const fs::path& inputFolder, const fs::path& folder) {
  if (auto* mesh = std::get_if<AuthoredConvexMesh>(&probe.proxy))
    mesh->meshAsWritten = mesh->mesh.lexically_relative(folder);
  if (probe.cubemap && fs::path(*probe.cubemap).is_relative())
    probe.cubemap =
        (inputFolder / *probe.cubemap).lexically_normal().lexically_relative(folder).string();
  return probe;
}

// The layout as a scene written into outFolder: the input's level, reached from there; with
// keepAuthored the input's probes first, as they are, then the added ones, named so that no
// name repeats.
Scene layoutScene(const Scene& input, const LayoutResult& layout, const fs::path& outFolder,
                  bool keepAuthored) {
  Scene scene;
  scene.fileUp = input.fileUp;
  scene.metersPerUnit = input.metersPerUnit;
  const fs::path folder = fs::absolute(outFolder).lexically_normal();
  scene.file = folder / "layout.scene.json";
  scene.level = input.level;
  for (LevelMeshRef& ref : scene.level) ref.pathAsWritten = ref.path.lexically_relative(folder);
  std::set<std::string> names;
  if (keepAuthored) {
    const fs::path inputFolder = fs::absolute(input.file).parent_path().lexically_normal();
    for (const Probe& p : input.probes) {
      scene.probes.push_back(keptProbe(p, inputFolder, folder));
      names.insert(p.name);
    }
  }
  std::size_t number = 0;
  for (std::size_t i = 0; i < layout.probes.size(); ++i) {
    char name[32];
    do std::snprintf(name, sizeof name, "probe_%03zu", ++number);
    while (names.count(name) > 0);
    Probe probe;
    probe.name = name;
    probe.captureMeters = layout.probes[i].captureMeters;
    probe.influence = layout.probes[i].influence;
    probe.proxy = AutoProxy{};
    scene.probes.push_back(std::move(probe));
  }
  return scene;
}

// The scene file says which proxy each probe has, so `build` on layout.scene.json keeps the
// same ones: boxes, spheres, cheap_k and none as written, a convex proxy as a mesh beside the
// scene. A shape no scene can hold stays `auto` (buildLayoutProxy keeps none). A convex shape
// becomes the one its mesh gives, as `survey` and `build` read it from the file:
// corners in floats, and those merged in polytopeFromPlanes stand within the merge distance
// of some of their planes (basement's median moved by 3e-6 deg between the two).
ProxySpec authoredSpec(ProxyShape& shape, const fs::path& meshFile, const std::string& name,
                       std::vector<std::pair<fs::path, LevelMesh>>& meshes) {
  if (!sceneFileCanHold(shape)) return AutoProxy{};
  if (std::holds_alternative<InfiniteShape>(shape)) return InfiniteProxy{};
  if (const auto* box = std::get_if<BoxShape>(&shape))
    return AuthoredObb{box->centerMeters, box->halfExtentsMeters, box->worldFromBox};
  if (const auto* sphere = std::get_if<SphereShape>(&shape))
    return AuthoredSphere{sphere->centerMeters, sphere->radiiMeters.x};
  if (const auto* cheapK = std::get_if<CheapKShape>(&shape))
    return AuthoredCheapK{cheapK->kPerMeter};
  if (const auto* convex = std::get_if<ConvexProxy>(&shape)) {
    LevelMesh mesh;
    for (const glm::dvec3& v : convex->verticesMeters) mesh.positionsMeters.emplace_back(v);
    mesh.triangles = convex->triangles;
    mesh.parts.push_back({name, meshFile, 0, static_cast<std::uint32_t>(mesh.triangles.size())});
    shape =
        convexFromMesh({mesh.positionsMeters.begin(), mesh.positionsMeters.end()}, mesh.triangles);
    meshes.emplace_back(meshFile, std::move(mesh));
    return AuthoredConvexMesh{meshFile, meshFile.filename()};
  }
  return AutoProxy{};
}

// The grid baseline is what engines give: box projection, the `aabb` candidate kept.
void keepAabbs(Scene& scene, std::vector<ProbeProxyBuild>& builds) {
  for (std::size_t i = 0; i < builds.size(); ++i) {
    for (std::size_t c = 0; c < builds[i].candidates.size(); ++c) {
      const ProxyCandidate& candidate = builds[i].candidates[c];
      if (candidate.origin != CandidateOrigin::Aabb) continue;
      builds[i].kept = c;
      const BoxShape& box = std::get<BoxShape>(candidate.shape);
      scene.probes[i].proxy = AuthoredBox{box.centerMeters, box.halfExtentsMeters};
    }
  }
}

// The added probes are chosen on coarse candidates; built for their ranges and blended with
// the artist's, one may do worse than the kept probes alone did there. Last added first, a
// probe goes when the survey without it has no more floor over the tolerance and none more
// uncovered: an artist's scene gets nothing that does not help it.
void dropAddedProbesThatDoNotHelp(const LevelRayCaster& level, const SurveyOptions& survey,
                                  std::vector<SurveyProbe>& probes, LayoutJobResult& r) {
  const std::size_t kept = r.scene.probes.size() - r.layout.probes.size();
  for (std::size_t i = r.scene.probes.size(); i-- > kept;) {
    std::vector<SurveyProbe> without = probes;
    without.erase(without.begin() + static_cast<std::ptrdiff_t>(i));
    SurveyResult lesser = surveyProbes(without, level, survey);
    const SurveyFigures &now = r.survey.figures, &then = lesser.figures;
    if (then.overToleranceShare > now.overToleranceShare ||
        then.uncoveredShare > now.uncoveredShare)
      continue;
    const auto at = static_cast<std::ptrdiff_t>(i);
    probes = std::move(without);
    r.scene.probes.erase(r.scene.probes.begin() + at);
    r.builds.erase(r.builds.begin() + at);
    r.layout.probes.erase(r.layout.probes.begin() + (at - static_cast<std::ptrdiff_t>(kept)));
    r.survey = std::move(lesser);
  }
}

nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

std::string layoutReportJson(const LayoutJobOptions& o, const LayoutJobResult& r) {
  nlohmann::ordered_json j;
  j["baseline"] =
      o.layout.baseline == LayoutBaseline::None ? "none" : baselineName(o.layout.baseline);
  j["probes"] = r.scene.probes.size();
  if (o.layout.keepAuthored) {
    j["kept_probes"] = r.scene.probes.size() - r.layout.probes.size();
    j["added_probes"] = r.layout.probes.size();
    j["kept_served_share"] = number(r.layout.keptServedShare);
  }
  j["tolerance_deg"] = r.toleranceDeg;
  j["seeded_from"] = r.seededFrom;
  j["seed_points"] = nlohmann::ordered_json::array();
  for (const glm::dvec3& s : r.seedPointsMeters) j["seed_points"].push_back({s.x, s.y, s.z});
  j["spacing_m"] = number(r.layout.spacingMeters);
  j["floor_cells"] = r.layout.floorCells;
  j["floor_samples"] = r.layout.floorSamples;
  j["capture_points"] = r.layout.capturePoints;
  j["candidates"] = r.layout.candidates;
  j["candidate_median_ms"] = number(r.layout.candidateMedianMs);
  if (r.layout.candidateWireBytes > 0) {  // --tile-size: what crossed between the tiles
    j["candidate_tiles"] = r.layout.tiles;
    j["candidate_wire_bytes"] = r.layout.candidateWireBytes;
  }
  j["served_share"] = number(r.layout.servedShare);
  j["servable_share"] = number(r.layout.servableShare);
  j["layout_seconds"] = number(r.layout.seconds);
  if (!r.layout.stageSeconds.empty()) {
    nlohmann::ordered_json stages;
    for (const auto& [stage, seconds] : r.layout.stageSeconds) stages[stage] = number(seconds);
    j["stage_seconds"] = stages;
  }
  if (!r.engines.empty()) {
    const auto policyJson = [](const EnginePresetPolicy& p) {
      nlohmann::ordered_json policy;
      policy["clip_to_influence"] = p.clipToInfluence;
      policy["fade_scale"] = p.fadeScale;
      policy["clear_the_floor"] = p.clearTheFloor;
      policy["cube_about_capture"] = p.cubeAboutCapture;
      policy["influence_inside"] = p.influenceInside;
      return policy;
    };
    nlohmann::ordered_json engines;
    for (const EnginePresetChoice& c : r.engines) {
      nlohmann::ordered_json e = policyJson(c.policy);
      e["tried"] = nlohmann::ordered_json::array();
      const auto figuresJson = [](nlohmann::ordered_json& to, const SurveyFigures& f) {
        to["p95_deg"] = number(f.p95Deg);
        to["over_tolerance_share"] = number(f.overToleranceShare);
        to["uncovered_share"] = number(f.uncoveredShare);
        to["occluded_share"] = number(f.occludedShare);
      };
      for (const EnginePresetTrial& t : c.trials) {
        nlohmann::ordered_json trial = policyJson(t.policy);
        figuresJson(trial, t.figures);
        // The best of its kind of box, with the probes' entries chosen under it.
        if (t.finished) figuresJson(trial["finished"], *t.finished);
        e["tried"].push_back(trial);
      }
      // Where the engine takes another box than `build` exports, or none: probe by probe.
      e["left_out"] = nlohmann::ordered_json::array();
      e["other_box"] = nlohmann::ordered_json::object();
      for (std::size_t i = 0; i < c.boxFrom.size(); ++i) {
        const std::string& name = r.scene.probes[i].name;
        if (c.boxFrom[i] == kLeftOut) e["left_out"].push_back(name);
        if (c.boxFrom[i] >= 0)
          e["other_box"][name] =
              candidateName(r.builds[i].candidates[static_cast<std::size_t>(c.boxFrom[i])]);
      }
      // The engine's priority field where the layout set it above the engine's default.
      const std::vector<int> priorities = enginePriorities(c.engine);
      if (!priorities.empty()) {
        e["priority"] = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < c.priority.size(); ++i)
          if (c.priority[i] != priorities.front())
            e["priority"][r.scene.probes[i].name] = c.priority[i];
      }
      // EEVEE's probes captured at their box's centre rather than at the scene's point.
      if (c.engine == Engine::Eevee) {
        e["at_box_centre"] = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < c.atBoxCentre.size(); ++i)
          if (c.atBoxCentre[i]) e["at_box_centre"].push_back(r.scene.probes[i].name);
      }
      SurveyResult named = c.survey;
      named.scene = baselineName(o.layout.baseline);
      e["survey"] = nlohmann::ordered_json::parse(surveyReportJson(named, r.scene.probes));
      engines[std::string(engineName(c.engine))] = e;
    }
    j["engines"] = engines;
  }
  j["survey"] = nlohmann::ordered_json::parse(surveyReportJson(r.survey, r.scene.probes));
  return j.dump(2) + "\n";
}

// The final proxies of the probes the layout added (scene and builds from `first` on), here or
// wherever options.buildProxies sends them: each is built from its task alone, so the bytes
// are the same wherever it ran.
void buildAddedProxies(const LevelRayCaster& rayCaster, const LayoutJobOptions& o,
                       double toleranceDeg, LayoutJobResult& r, std::size_t first) {
  std::vector<InfluenceVolume> volumes;
  for (const Probe& probe : r.scene.probes) volumes.push_back(probe.influence);
  std::vector<ProxyBuildTask> tasks(r.builds.size() - first);
  for (std::size_t i = first; i < r.builds.size(); ++i) {
    ProxyBuildTask& t = tasks[i - first];
    t.probe = r.scene.probes[i];
    t.candidateFitMeters = r.layout.probes[i - first].fitMeters;
    t.blendVolumes = volumesMeeting(volumes, i, t.blendIndex);
  }
  if (!o.buildProxies) {
    tbb::parallel_for(first, r.builds.size(), [&](std::size_t i) {
      const ProxyBuildTask& t = tasks[i - first];
      r.builds[i] = buildLayoutProxy(rayCaster, t.probe, o.layout.finalProxy, t.candidateFitMeters,
                                     toleranceDeg, {t.blendVolumes, t.blendIndex});
    });
    return;
  }
  std::vector<std::string> packed;
  for (const ProxyBuildTask& t : tasks) packed.push_back(packProxyBuildTask(t));
  const std::vector<std::string> wires = o.buildProxies(packed);
  if (wires.size() != packed.size())
    throw InputError("proxy build wire", std::to_string(wires.size()) + " builds came back for " +
                                             std::to_string(packed.size()) + " probes");
  for (std::size_t i = first; i < r.builds.size(); ++i) {
    r.builds[i] = unpackProxyBuild(wires[i - first]);
    if (r.builds[i].probe != r.scene.probes[i].name)
      throw InputError("proxy build wire", "the build of " + r.builds[i].probe + " came back for " +
                                               r.scene.probes[i].name);
  }
}

// The median height of the probes' capture points over the floor right under them; none when
// no probe stands over a floor.
std::optional<double> authoredCaptureHeight(const LevelRayCaster& level,
                                            std::span<const Probe> probes) {
  std::vector<glm::dvec3> captures;
  for (const Probe& p : probes) captures.push_back(p.captureMeters);
  std::vector<double> heights;
  for (const VerticalView& v : lookUpAndDown(level, captures))
    if (std::isfinite(v.floorBelowMeters)) heights.push_back(v.floorBelowMeters);
  if (heights.empty()) return std::nullopt;
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  return heights[heights.size() / 2];
}

}  // namespace

void LayoutJobOptions::check() const {
  checkAsGiven(layout, given);
  checkAsGiven(survey, given);
  if (survey.engine != Engine::Generic)
    throw InputError("option engine", "a layout's engines are LayoutJobOptions::engines");
  if (!outFolder.empty()) checkOutputFolder(outFolder);
}

LayoutJobResult runLayoutJob(const LayoutJobOptions& o, const Progress& progress) {
  o.check();
  const ThreadLimit threads(o.threads);
  LayoutSetup setup = prepareLayout(o);
  const Scene& input = setup.input;
  const LevelRayCaster& rayCaster = *setup.rayCaster;
  LayoutOptions& layout = setup.layout;
  SurveyOptions& survey = setup.survey;
  LayoutJobResult r;
  r.toleranceDeg = layout.toleranceDeg;
  r.seedPointsMeters = setup.seedsMeters;
  r.seededFrom = setup.seededFrom;
  const std::vector<glm::dvec3>& seeds = r.seedPointsMeters;

  // The artist's probes, with the proxies `build` gives them (authored ones as authored).
  std::vector<ProbeProxyBuild> keptBuilds;
  std::vector<SurveyProbe> kept;
  if (o.layout.keepAuthored) {
    // Probes added beside an artist's are captured at the artist's height: beside the pillared
    // hall's probes at 1.6 m, added probes at the 0.6 m default left its p95 at 9.0 deg, at
    // 1.6 m 0.30 deg.
    if (!o.captureHeightGiven)
      if (const std::optional<double> height = authoredCaptureHeight(rayCaster, input.probes))
        layout.captureHeightMeters = *height;
    keptBuilds = buildSceneProxies(input, rayCaster, o.layout.finalProxy);
    for (std::size_t i = 0; i < input.probes.size(); ++i)
      kept.push_back({input.probes[i].captureMeters, input.probes[i].influence,
                      keptBuilds[i].candidates[keptBuilds[i].kept].shape});
  }

  // Every point of the floor the survey walks must lie in a volume.
  layout.coverFloor = survey.floor;
  r.layout = runLayout(rayCaster, seeds, layout, progress, kept);
  // The job's own stages after the layout's, told the same way.
  auto lapStart = std::chrono::steady_clock::now();
  const auto stageDone = [&](std::string_view stage) {
    const auto now = std::chrono::steady_clock::now();
    if (layout.onStageDone)
      layout.onStageDone(stage, std::chrono::duration<double>(now - lapStart).count());
    lapStart = now;
  };
  r.scene = layoutScene(input, r.layout, o.outFolder.empty() ? fs::path(".") : o.outFolder,
                        o.layout.keepAuthored);
  std::vector<std::pair<fs::path, LevelMesh>> proxyMeshes;  // written with the scene
  if (o.layout.baseline == LayoutBaseline::None) {
    checkCapturePoints(r.scene, rayCaster);
    r.builds = std::move(keptBuilds);
    const std::size_t first = r.builds.size();  // the added probes' builds follow the kept ones
    r.builds.resize(r.scene.probes.size());
    buildAddedProxies(rayCaster, o, layout.toleranceDeg, r, first);
    stageDone("proxies");
    const fs::path folder = r.scene.file.parent_path();
    for (std::size_t i = first; i < r.builds.size(); ++i) {
      Probe& probe = r.scene.probes[i];
      probe.proxy = authoredSpec(r.builds[i].candidates[r.builds[i].kept].shape,
                                 folder / (probe.name + ".ply"), probe.name, proxyMeshes);
    }
  } else {
    r.scene = sceneAsWritten(r.scene, r.scene.file);  // built from what the file will hold
    r.builds = buildSceneProxies(r.scene, rayCaster, o.layout.finalProxy);
    if (o.layout.baseline == LayoutBaseline::Grid) keepAabbs(r.scene, r.builds);
  }

  // Measure what a survey of the written scene reads: its coordinates rounded as the file
  // spells them, and the authored boxes and spheres made from them.
  r.scene = sceneAsWritten(r.scene, r.scene.file);
  for (std::size_t i = 0; i < r.scene.probes.size(); ++i) {
    const ProxySpec& spec = r.scene.probes[i].proxy;
    if (std::holds_alternative<AuthoredConvexMesh>(spec)) continue;  // made from its mesh
    if (std::optional<ProxyShape> read = authoredProxyShape(spec, r.scene))
      r.builds[i].candidates[r.builds[i].kept].shape = std::move(*read);
  }
  std::vector<SurveyProbe> probes;
  for (std::size_t i = 0; i < r.scene.probes.size(); ++i)
    probes.push_back({r.scene.probes[i].captureMeters, r.scene.probes[i].influence,
                      r.builds[i].candidates[r.builds[i].kept].shape});
  survey.seedPointsMeters = seeds;
  survey.toleranceDeg = layout.toleranceDeg;
  // A later survey, validate or add-on run of the scene measures this floor, this way.
  r.scene.measuredWith = measuredWith(survey, seeds);
  r.survey = surveyProbes(probes, rayCaster, survey);
  stageDone("survey");
  if (o.layout.keepAuthored) {
    dropAddedProbesThatDoNotHelp(rayCaster, survey, probes, r);
    // The dropped probes' proxy meshes are not written.
    std::erase_if(proxyMeshes, [&](const auto& mesh) {
      return std::none_of(r.scene.probes.begin(), r.scene.probes.end(), [&](const Probe& p) {
        const auto* convex = std::get_if<AuthoredConvexMesh>(&p.proxy);
        return convex != nullptr && convex->mesh == mesh.first;
      });
    });
  }
  if (!o.engines.empty()) {
    const SurveyFloor floor = prepareSurveyFloor(seeds, rayCaster, survey);
    SurveyOptions trial = survey;
    trial.samplesPerCell = std::min(survey.samplesPerCell, kEngineTrialSamplesPerCell);
    const double cells = double(floor.samples.size()) / std::max(1, floor.samplesPerCell);
    double scale = 1.0;
    while (cells / (scale * scale) * trial.samplesPerCell > kMaxEngineTrialSamples) scale *= 2.0;
    trial.floor.gridSpacingMeters = survey.floor.gridSpacingMeters * scale;
    const SurveyFloor trialFloor = prepareSurveyFloor(seeds, rayCaster, trial);
    // The artist's probes come first in the scene and stay in every engine.
    const ProbeEntries entries{o.layout.baseline == LayoutBaseline::None,
                               o.layout.keepAuthored ? input.probes.size() : 0};
    // A stage an engine: one engine's option search can take most of a run.
    r.engines = choosePresetsForEngines(
        o.engines, r.scene, r.builds, rayCaster, floor, trialFloor, survey, entries,
        [&](Engine engine) { stageDone("engine " + std::string(engineName(engine))); });
    if (o.engines.size() == 1 && !r.engines.empty()) r.survey = r.engines.front().survey;
  }
  r.survey.scene = baselineName(o.layout.baseline);
  r.json = layoutReportJson(o, r);

  if (!o.outFolder.empty()) {
    fs::create_directories(o.outFolder);
    for (const auto& [file, mesh] : proxyMeshes) {
      writeLevelMeshFile(mesh, file, UpAxis::Z);
      r.written.push_back(file);
    }
    writeSceneFile(r.scene, o.outFolder / "layout.scene.json");
    writeRuntimeExport(r.scene, exportForEngines(r.scene, r.builds, r.engines), o.outFolder);
    for (const char* name : {"layout.scene.json", "proxies.json", "proxies.glb", "layout.json"})
      r.written.push_back(o.outFolder / name);
    writeFileAtomically(o.outFolder / "layout.json", r.json);
    for (const fs::path& map : writeSurveyMaps(r.survey, r.scene.probes, o.outFolder, o.maps))
      r.written.push_back(map);
  }
  return r;
}

}  // namespace probeproxy::jobs
