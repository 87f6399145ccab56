#include "core/errors/input_error.h"
#include "plugin/cli/verb.h"

#include <iostream>
#include <memory>
#include <string>

namespace probeproxy::cli {

namespace {

// A verb whose issue has not landed: its options are the real ones so --help tells the truth
// about the interface, but running it says plainly what is missing.
Verb pendingVerb(CLI::App* command, std::string what, int issue) {
  return {command, [command, what = std::move(what), issue] {
            std::cerr << "probeproxy " << command->get_name() << ": not available yet: " << what
                      << " lands with issue " << issue << "\n";
            return kExitBadInput;
          }};
}

// CLI11 binds options to variables that must outlive parsing; pending verbs only need the
// parse to succeed, so the values live in one holder for the life of the program.
struct PendingOptions {
  std::string scene, out, probe, camera, plane, at;
  bool json = false;
};

}  // namespace

std::vector<Verb> addPendingVerbs(CLI::App& app) {
  static PendingOptions o;
  std::vector<Verb> verbs;


  CLI::App* blend = app.add_subcommand(
      "blend", "Mix the probes that influence a point of interest into one cubemap");
  blend->add_option("scene", o.scene, "scene file (*.scene.json)")->required();
  blend->add_option("--at", o.at, "point of interest X,Y,Z")->required();
  blend->add_option("--out", o.out, "output EXR")->required();
  verbs.push_back(pendingVerb(blend, "probe blending", 5));

  return verbs;
}

}  // namespace probeproxy::cli
