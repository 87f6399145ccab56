// `probeproxy demo`: flags into the demo job (plugin/jobs/demo/), its account on stdout.

#include "plugin/cli/verb.h"
#include "plugin/jobs/demo/demo_job.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

Verb addDemoVerb(CLI::App& app) {
  auto o = std::make_shared<jobs::DemoJobOptions>();
  CLI::App* demo = app.add_subcommand(
      "demo", "Run the main job end to end on the built-in level and say what it did");
  demo->add_option("--out", o->outFolder, "output folder")->capture_default_str();
  demo->add_option("--face-size", o->faceSize, "depth cube face size in texels (8-2048)")
      ->capture_default_str();
  demo->add_flag("!--no-bench", o->bench, "skip the speed-against-accuracy benchmark and charts");
  return {demo, [o] {
            jobs::runDemoJob(*o, std::cout);
            return 0;
          }};
}

}  // namespace probeproxy::cli
