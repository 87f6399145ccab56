// `probeproxy build` and `probeproxy export`: flags into the build job (plugin/jobs/build/),
// its report printed.

#include "plugin/cli/terminal_progress.h"
#include "plugin/cli/verb.h"
#include "plugin/jobs/build/build_job.h"
#include "plugin/jobs/build/build_report.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct BuildVerbOptions {
  std::string scene, out;
  bool json = false;
  bool table = true;  // `export` writes the same files without the candidate table
  jobs::BuildJobOptions job;
};

int runBuild(BuildVerbOptions o) {
  o.job.input.file = o.scene;
  o.job.outFolder = o.out;
  const jobs::BuildJobResult result =
      jobs::runBuildJob(o.job, terminalProgress("probeproxy build", "probes"));
  for (const ProbeProxyBuild& b : result.builds) {
    for (const std::string& finding : b.findings)
      std::cerr << "probe " << b.probe << ": " << finding << "\n";
  }
  if (o.json) {
    std::cout << jobs::buildReportJson(result.builds);
  } else {
    if (o.table) jobs::printBuildTable(std::cout, result.builds);
    std::cout << "wrote " << result.proxiesJson.string() << " and proxies.glb\n";
  }
  return 0;
}

// Ranges are the job's to check (ProxyBuildOptions::check), so the CLI and the add-on refuse
// the same values with the same line.
void addProxyOptions(CLI::App* verb, BuildVerbOptions& o) {
  ProxyBuildOptions& p = o.job.proxy;
  verb->add_option("scene", o.scene, "scene file (*.scene.json)")->required();
  verb->add_option("--out", o.out, "output folder for proxies.json and proxies.glb")->required();
  verb->add_flag("--json", o.json, "print the build report as JSON on stdout");
  verb->add_option("--tolerance-deg", p.toleranceDeg,
                   "keep the fewest planes whose mirror_floor p95 angular error is under this")
      ->capture_default_str();
  verb->add_option("--max-planes", p.maxPlanes, "never keep more planes than this (4-256)")
      ->capture_default_str();
  verb->add_option("--max-miss-rate", p.maxMissRate,
                   "share of visible samples a kept proxy may miss (0-1)")
      ->capture_default_str();
  verb->add_option("--face-size", p.depthFaceSize, "depth cube face size in texels (8-2048)")
      ->capture_default_str();
  verb->add_option("--samples", p.samples.targetSamples, "reflection samples per set (64-1e6)")
      ->capture_default_str();
  verb->add_flag("--regenerate", p.regenerate,
                 "generate a proxy also where the scene authors one (which is measured beside)");
  verb->add_option("--threads", o.job.threads, "worker threads (0: all cores)")
      ->capture_default_str();
}

}  // namespace

Verb addBuildVerb(CLI::App& app) {
  auto o = std::make_shared<BuildVerbOptions>();
  CLI::App* build = app.add_subcommand(
      "build", "Build each probe's convex proxy from the level, measure every candidate, export");
  addProxyOptions(build, *o);
  return {build, [o] { return runBuild(*o); }};
}

Verb addExportVerb(CLI::App& app) {
  auto o = std::make_shared<BuildVerbOptions>();
  o->table = false;
  CLI::App* exportVerb = app.add_subcommand(
      "export",
      "Write proxies.json and proxies.glb for the game runtime: authored proxies as "
      "they are, `auto` ones generated");
  addProxyOptions(exportVerb, *o);
  return {exportVerb, [o] { return runBuild(*o); }};
}

}  // namespace probeproxy::cli
