// `probeproxy survey`: flags into the survey job (plugin/jobs/survey/), its figures printed (a
// table, or the JSON report under --json); with --out the job writes survey.json and the maps.

#include "core/errors/input_error.h"
#include "plugin/cli/command_line_values.h"
#include "plugin/cli/measure_options.h"
#include "plugin/cli/terminal_progress.h"
#include "plugin/cli/verb.h"
#include "plugin/jobs/survey/survey_job.h"
#include "plugin/jobs/survey/survey_report.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct SurveyVerbOptions {
  std::string scene, out, proxies;
  bool json = false;
  std::string scheme = "lagarde";
  std::string proxy = "scene";
  std::string engine = "generic";
  std::vector<std::string> seeds;
  std::string maxMemory;
  jobs::SurveyJobOptions job;
};

SurveyProxies surveyProxies(const std::string& name) {
  if (name == "scene") return SurveyProxies::Scene;
  if (name == "aabb") return SurveyProxies::BestAabb;
  if (name == "infinite") return SurveyProxies::Infinite;
  throw InputError("--proxy", "expected scene, aabb or infinite, got '" + name + "'");
}

int runSurveyVerb(SurveyVerbOptions o) {
  const std::optional<BlendScheme> scheme = blendSchemeFromName(o.scheme);
  if (!scheme)
    throw InputError("--scheme", "expected lagarde or enlighten, got '" + o.scheme + "'");
  o.job.survey.blend.scheme = *scheme;
  o.job.survey.proxies = surveyProxies(o.proxy);
  o.job.survey.engine = parseEngine(o.engine);
  if (!o.maxMemory.empty())
    o.job.survey.maxMemoryBytes = parseMemorySize(o.maxMemory, "--max-memory");
  o.job.survey.proxiesJson = o.proxies;
  parseSeeds(o.seeds, o.job.given);
  o.job.input.file = o.scene;
  o.job.outFolder = o.out;
  const jobs::SurveyJobResult r =
      jobs::runSurveyJob(o.job, terminalProgress("probeproxy survey: proxies", "probes"));
  if (o.json)
    std::cout << r.json;
  else
    jobs::printSurveyTable(std::cout, r.result, r.probes);
  for (const std::filesystem::path& file : r.written)
    std::cerr << "wrote " << file.string() << "\n";
  return 0;
}

}  // namespace

Verb addSurveyVerb(CLI::App& app) {
  auto o = std::make_shared<SurveyVerbOptions>();
  SurveyOptions& s = o->job.survey;
  CLI::App* verb = app.add_subcommand(
      "survey",
      "Measure what a player sees across the whole walkable floor, every probe blended as the "
      "runtime blends it: area-weighted error figures and an error map");
  verb->add_option("scene", o->scene, "scene file (*.scene.json)")->required();
  verb->add_flag("--json", o->json, "print the figures as JSON on stdout");
  verb->add_option("--out", o->out, "folder for survey.json and the error maps (PNG)");
  verb->add_flag("--probe-names", o->job.maps.probeNames,
                 "label each capture point on the error maps with its probe's name");
  verb->add_option("--engine", o->engine,
                   "whose renderer to measure: generic (the scene's proxies, --scheme blend), "
                   "unity, unity-hdrp, unreal, godot3, godot4, bevy or eevee (the presets a "
                   "build exports for that engine, blended by its rules; docs/engines.md)")
      ->capture_default_str();
  verb->add_option("--scheme", o->scheme,
                   "blend weights: lagarde (Lagarde & Zanuttini 2012) or enlighten (the Enlighten "
                   "documentation)")
      ->capture_default_str();
  verb->add_option("--max-probes", s.blend.maxProbes, "blend at most this many probes (1-64)")
      ->capture_default_str();
  verb->add_option("--proxies", o->proxies,
                   "look probes up through the kept proxies of this build export (proxies.json)");
  verb->add_option("--proxy", o->proxy,
                   "scene: authored or built (or --proxies); aabb: the build's aabb candidate; "
                   "infinite: no correction")
      ->capture_default_str();
  addMeasureOptions(*verb, o->job.given, o->seeds,
                    "over_tolerance_share counts floor whose error exceeds this, degrees");
  verb->add_option("--samples-per-cell", s.samplesPerCell, "reflection samples per floor cell")
      ->capture_default_str();
  verb->add_option("--max-samples", s.maxSamples, "fewer samples per cell beyond this many")
      ->capture_default_str();
  verb->add_option("--sample-seed", s.seed, "random seed of the floor samples")
      ->capture_default_str();
  verb->add_option("--threads", o->job.threads, "worker threads (0: all cores)")
      ->capture_default_str();
  verb->add_option(
      "--max-memory", o->maxMemory,
      "at most this much memory, e.g. 4G or 512M: the floor's estimate is checked before the work "
      "that needs it, and a level that would need more is refused (default: what "
      "the machine or ulimit gives)");
  return {verb, [o] { return runSurveyVerb(*o); }};
}

}  // namespace probeproxy::cli
