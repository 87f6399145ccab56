// `probeproxy validate`: flags into the validate job (plugin/jobs/validate/), its findings
// printed; exit 1 on any error or warning.

#include "plugin/cli/measure_options.h"
#include "plugin/cli/verb.h"
#include "plugin/jobs/validate/validate_job.h"
#include "plugin/jobs/validate/validate_report.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct ValidateVerbOptions {
  std::string scene;
  bool json = false;
  std::vector<std::string> seeds;
  jobs::ValidateJobOptions job;
};

int runValidate(ValidateVerbOptions o) {
  parseSeeds(o.seeds, o.job.given);
  o.job.input.file = o.scene;
  const jobs::ValidateJobResult result = jobs::runValidateJob(o.job);
  if (o.json)
    std::cout << jobs::validateReportJson(result.findings);
  else
    jobs::printFindings(std::cout, o.scene, result.findings);
  // Errors and warnings fail a pipeline; info findings are reported but leave it clean.
  return result.fails ? 1 : 0;
}

}  // namespace

Verb addValidateVerb(CLI::App& app) {
  auto o = std::make_shared<ValidateVerbOptions>();
  ValidateOptions& v = o->job.validate;
  CLI::App* verb = app.add_subcommand(
      "validate",
      "Check authored proxies and influence volumes against the level (exit 0 clean, 1 "
      "errors or warnings, 2 bad input)");
  verb->add_option("scene", o->scene, "scene file (*.scene.json)")->required();
  verb->add_flag("--json", o->json, "print the findings as JSON on stdout");
  verb->add_option("--max-overlap", v.maxOverlap,
                   "too_many_overlaps: most influence volumes allowed at one point")
      ->capture_default_str();
  verb->add_option("--max-uncovered-m2", v.maxUncoveredFloorSquareMeters,
                   "floor_not_covered: walkable floor allowed outside every influence volume")
      ->capture_default_str();
  verb->add_option("--max-leak-share", v.maxLeakShare,
                   "influence_leak: share of a volume's floor allowed hidden from its probe")
      ->capture_default_str();
  verb->add_option("--max-inner-overlap-m3", v.maxInnerOverlapCubicMeters,
                   "inner_ranges_overlap: volume two inner ranges may share")
      ->capture_default_str();
  verb->add_option("--max-weight-jump", v.maxWeightJumpPerCentimeter,
                   "weight_jump: largest blend-weight change per centimetre")
      ->capture_default_str();
  verb->add_flag("--glossy", v.glossyReceivers,
                 "reflected_camera_outside_proxy: receivers are glossy, so the reflected "
                 "camera itself must be inside the proxy (Lagarde & Zanuttini 2012)");
  addMeasureOptions(*verb, o->job.given, o->seeds,
                    "proxy_error_over_tolerance: largest mirror_floor p95 angular error on the "
                    "floor a probe serves, degrees",
                    v.toleranceDeg);
  verb->add_option("--samples", v.samples.targetSamples, "reflection samples per probe")
      ->capture_default_str();
  verb->add_option("--rules", v.rules,
                   "measure only these rules (comma-separated: " + selectableRuleNames() +
                       "); the mesh and capture checks always run")
      ->delimiter(',');
  verb->add_option("--threads", o->job.threads, "worker threads (0: all cores)")
      ->capture_default_str();
  return {verb, [o] { return runValidate(*o); }};
}

}  // namespace probeproxy::cli
