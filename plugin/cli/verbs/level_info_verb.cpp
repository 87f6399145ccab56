// `probeproxy level-info LEVEL [--map maps/NAME.bsp]` (hidden: a utility for scripts, not one
// of the product's verbs): flags into the level-info job, its JSON printed.

#include "plugin/cli/verb.h"
#include "plugin/jobs/level_info/level_info_job.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

Verb addLevelInfoVerb(CLI::App& app) {
  auto o = std::make_shared<jobs::LevelInfoJobOptions>();
  CLI::App* verb = app.add_subcommand(
      "level-info", "Print a Quake 3 BSP level's figures, spawn points and lights as JSON");
  verb->group("");  // hidden from --help: a utility for scripts/corpus, not a product verb
  verb->add_option("level", o->level, ".bsp file, or .pk3 archive with --map")->required();
  verb->add_option("--map", o->map, "the .bsp inside the .pk3, e.g. maps/downer.bsp");
  return {verb, [o] {
            std::cout << jobs::runLevelInfoJob(*o);
            return 0;
          }};
}

}  // namespace probeproxy::cli
