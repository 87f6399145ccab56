// `probeproxy layout`: flags into the layout job (plugin/jobs/layout/), its figures printed (a
// line of layout figures and the survey's table, or layout.json under --json); with --out the
// job writes the layout's scene, export, figures and error maps.

#include "core/errors/input_error.h"
#include "plugin/cli/command_line_values.h"
#include "plugin/cli/measure_options.h"
#include "plugin/cli/terminal_progress.h"
#include "plugin/cli/verb.h"
#include "plugin/jobs/layout/layout_job.h"
#include "plugin/jobs/survey/survey_report.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct LayoutVerbOptions {
  std::string input, out;
  std::string baseline = "none";
  std::string engine = "generic";
  std::vector<std::string> seeds;
  bool json = false;
  std::string maxMemory;
  jobs::LayoutJobOptions job;
};

LayoutBaseline layoutBaseline(const std::string& name) {
  if (name == "none") return LayoutBaseline::None;
  if (name == "grid") return LayoutBaseline::Grid;
  if (name == "spawn") return LayoutBaseline::Spawn;
  throw InputError("--baseline", "expected none, grid or spawn, got '" + name + "'");
}

int runLayoutVerb(LayoutVerbOptions o) {
  o.job.layout.baseline = layoutBaseline(o.baseline);
  o.job.engines = parseEngines(o.engine);
  if (o.job.engines == std::vector<Engine>{Engine::Generic}) o.job.engines.clear();
  parseSeeds(o.seeds, o.job.given);
  if (!o.maxMemory.empty())
    o.job.layout.maxMemoryBytes = o.job.survey.maxMemoryBytes =
        parseMemorySize(o.maxMemory, "--max-memory");
  o.job.levelOrScene = o.input;
  o.job.outFolder = o.out;
  // A line a stage, terminal or log: on an open level the stages after the candidates' run for
  // most of an hour.
  o.job.layout.onStageDone = [](std::string_view stage, double seconds) {
    std::fprintf(stderr, "probeproxy layout: %.*s done in %.1f s\n", static_cast<int>(stage.size()),
                 stage.data(), seconds);
  };
  const jobs::LayoutJobResult r =
      jobs::runLayoutJob(o.job, terminalProgress("probeproxy layout: candidates", "candidates"));
  if (o.json) {
    std::cout << r.json;
  } else {
    char line[300];
    if (o.job.layout.baseline == LayoutBaseline::None) {
      std::snprintf(
          line, sizeof line,
          "%zu probes from %zu capture points (%zu candidate proxies, median %.1f ms each), "
          "spacing %.2f m, %.1f%% of the floor served within %.2f deg by one probe (%.1f%% "
          "servable), %.1f s\n",
          r.scene.probes.size(), r.layout.capturePoints, r.layout.candidates,
          r.layout.candidateMedianMs, r.layout.spacingMeters, 100.0 * r.layout.servedShare,
          o.job.layout.toleranceDeg, 100.0 * r.layout.servableShare, r.layout.seconds);
    } else {
      std::snprintf(line, sizeof line, "%zu probes of the %s baseline, spacing %.2f m, %.1f s\n",
                    r.scene.probes.size(), o.baseline.c_str(), r.layout.spacingMeters,
                    r.layout.seconds);
    }
    std::cout << line;
    jobs::printSurveyTable(std::cout, r.survey, r.scene.probes);
  }
  if (r.seededFrom == "the level's floor regions") {
    std::cerr << "probeproxy layout: the level has no spawn points or probes: its floor is "
                 "flood-filled from its "
              << r.seedPointsMeters.size()
              << " floor region(s) (layout.json's seed_points; --seed X,Y,Z names others)\n";
  }
  for (const std::filesystem::path& file : r.written)
    std::cerr << "wrote " << file.string() << "\n";
  return 0;
}

}  // namespace

Verb addLayoutVerb(CLI::App& app) {
  auto o = std::make_shared<LayoutVerbOptions>();
  LayoutOptions& l = o->job.layout;
  CLI::App* verb = app.add_subcommand(
      "layout",
      "Place the fewest probes that serve the level's walkable floor within the tolerance, "
      "with their influence volumes and proxies, and survey the result; or a baseline layout");
  verb->add_option("level_or_scene", o->input,
                   "a scene file (*.scene.json) or a level (.glb .gltf .obj .ply .off .bsp)")
      ->required();
  verb->add_option("--out", o->out,
                   "folder for layout.scene.json, proxies.json/.glb, layout.json and the maps");
  verb->add_flag("--probe-names", o->job.maps.probeNames,
                 "label each capture point on the error maps with its probe's name");
  verb->add_flag("--json", o->json, "print layout.json on stdout");
  verb->add_option("--engine", o->engine,
                   "the engines the level ships to, comma-separated, or all: each gets the "
                   "presets it renders best (of a few box cuts, fade widths and floor "
                   "clearances) and its own figures: unity, unity-hdrp, unreal, godot3, godot4, "
                   "bevy, eevee; generic: the convex proxies alone (docs/engines.md)")
      ->capture_default_str();
  verb->add_option("--baseline", o->baseline,
                   "none: the layout; grid: a probe every --spacing m with aabb proxies; "
                   "spawn: a sphere of --reach m at every spawn point")
      ->capture_default_str();
  verb->add_flag("--keep-authored", l.keepAuthored,
                 "keep the scene's probes as they are and add probes only where they do not "
                 "serve the floor within the tolerance");
  addMeasureOptions(*verb, o->job.given, o->seeds,
                    "a floor sample is served where one probe's error is at most this, degrees");
  verb->add_option("--max-probes", l.maxProbes,
                   "at most this many probes, fills included (0: as many as the floor needs); "
                   "floor they leave stays uncovered")
      ->capture_default_str();
  verb->add_option("--spacing", l.spacingMeters, "the candidates' (and the grid's) spacing, m")
      ->capture_default_str();
  verb->add_option("--max-candidates", l.maxCandidates,
                   "at most this many capture points; the spacing coarsens to fit")
      ->capture_default_str();
  verb->add_option("--tile-size", l.tileMeters,
                   "judge the capture points a square tile of the floor this wide at a time, "
                   "each tile's candidates packed as for another process (the same layout, "
                   "bytes for bytes), m (0: all at once)")
      ->capture_default_str();
  verb->add_option("--reach", l.reachMeters,
                   "a candidate serves floor within this distance, m (0: all it sees)")
      ->capture_default_str();
  verb->add_option("--capture-height", l.captureHeightMeters,
                   "capture points this far above the floor (at most half the free height; "
                   "with --keep-authored, by default as high as the scene's probes), m")
      ->capture_default_str()
      ->each([o](const std::string&) { o->job.captureHeightGiven = true; });
  verb->add_option("--blend-band", l.blendBandMeters,
                   "gap between neighbouring inner ranges, where they blend (outer ranges "
                   "reach 1.5x as far), m")
      ->capture_default_str();
  verb->add_option("--threads", o->job.threads, "worker threads (0: all cores)")
      ->capture_default_str();
  verb->add_option(
      "--max-memory", o->maxMemory,
      "at most this much memory, e.g. 4G or 512M: the floor's estimate is checked before the work "
      "that needs it, and a level that would need more is refused (default: what "
      "the machine or ulimit gives)");
  return {verb, [o] { return runLayoutVerb(*o); }};
}

}  // namespace probeproxy::cli
