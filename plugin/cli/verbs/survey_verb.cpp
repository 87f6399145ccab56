// `probeproxy survey`: the level-wide error (geometry/survey/run_survey.h). Parses, runs the
// survey, prints the figures (a table, or the DESIGN.md JSON under --json) and, with --out,
// writes survey.json and the error maps.

#include "core/io/atomic_write.h"
#include "geometry/level/load_level.h"
#include "geometry/scene/scene_file.h"
#include "geometry/survey/run_survey.h"
#include "geometry/survey/survey_map.h"
#include "geometry/survey/survey_report.h"
#include "plugin/cli/verb.h"

#include <tbb/global_control.h>

#include <unistd.h>

#include <iostream>
#include <memory>
#include <optional>

namespace probeproxy::cli {

namespace {

struct SurveyVerbOptions {
  std::string scene;
  bool json = false;
  std::string out;
  std::string scheme = "lagarde";
  std::string proxy = "scene";
  std::string proxies;
  int threads = 0;  // 0: all cores
  SurveyOptions survey;
};

int runSurveyVerb(SurveyVerbOptions& o) {
  std::optional<tbb::global_control> threadLimit;
  if (o.threads > 0) threadLimit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
  o.survey.blend.scheme = *blendSchemeFromName(o.scheme);
  o.survey.proxies = o.proxy == "infinite" ? SurveyProxies::Infinite
                     : o.proxy == "aabb"   ? SurveyProxies::BestAabb
                                           : SurveyProxies::Scene;
  o.survey.proxiesJson = o.proxies;
  o.survey.check();  // before the level loads: a bad option is one line, at once
  const Scene scene = readSceneFile(o.scene);
  const LevelMesh level = loadLevel(scene);
  const LevelRayCaster rayCaster(level);
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  bool built = false;
  const SurveyResult result =
      runSurvey(scene, rayCaster, o.survey, [&](std::size_t done, std::size_t total) {
        built = true;
        if (terminal)
          std::cerr << "\rprobeproxy survey: proxies " << done << "/" << total << " probes"
                    << std::flush;
      });
  if (terminal && built) std::cerr << "\n";
  const std::string json = surveyReportJson(result);
  if (o.json)
    std::cout << json;
  else
    printSurveyTable(std::cout, result);
  if (!o.out.empty()) {
    writeFileAtomically(std::filesystem::path(o.out) / "survey.json", json);
    for (const auto& file : writeSurveyMaps(result, scene.probes, o.out))
      std::cerr << "wrote " << file.string() << "\n";
  }
  return 0;
}

}  // namespace

Verb addSurveyVerb(CLI::App& app) {
  auto o = std::make_shared<SurveyVerbOptions>();
  SurveyOptions& s = o->survey;
  CLI::App* verb = app.add_subcommand(
      "survey",
      "Measure what a player sees across the whole walkable floor, every probe blended as the "
      "runtime blends it: area-weighted error figures and an error map");
  verb->add_option("scene", o->scene, "scene file (*.scene.json)")->required();
  verb->add_flag("--json", o->json, "print the figures as JSON on stdout");
  verb->add_option("--out", o->out, "folder for survey.json and the error maps (PNG)");
  verb->add_option("--scheme", o->scheme,
                   "blend weights: lagarde (seed 000) or enlighten (seed 004)")
      ->capture_default_str()
      ->check(CLI::IsMember({"lagarde", "enlighten"}));
  verb->add_option("--max-probes", s.blend.maxProbes, "blend at most this many probes")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  verb->add_option("--tolerance-deg", s.toleranceDeg,
                   "over_tolerance_share counts floor whose error exceeds this")
      ->capture_default_str();
  verb->add_option("--proxies", o->proxies,
                   "look probes up through the kept proxies of this build export (proxies.json)");
  verb->add_option("--proxy", o->proxy,
                   "scene: authored or built (or --proxies); aabb: the build's aabb candidate; "
                   "infinite: no correction")
      ->capture_default_str()
      ->check(CLI::IsMember({"scene", "aabb", "infinite"}));
  verb->add_option("--grid", s.floor.gridSpacingMeters, "walkable-floor cell size, m")
      ->capture_default_str();
  verb->add_option("--step-height", s.floor.stepHeightMeters,
                   "largest height a player steps up between neighbouring cells, m")
      ->capture_default_str();
  verb->add_option("--head-clearance", s.floor.headClearanceMeters,
                   "free height walkable floor needs above it, m")
      ->capture_default_str();
  verb->add_option("--samples-per-cell", s.samplesPerCell, "reflection samples per floor cell")
      ->capture_default_str();
  verb->add_option("--max-samples", s.maxSamples, "fewer samples per cell beyond this many")
      ->capture_default_str();
  verb->add_option("--seed", s.seed, "random seed of the samples")->capture_default_str();
  verb->add_option("--threads", o->threads, "worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  return {verb, [o] { return runSurveyVerb(*o); }};
}

}  // namespace probeproxy::cli
