#include "plugin/cli/command_line.h"

#include "core/errors/input_error.h"
#include "core/scene/scene_limits.h"
#include "plugin/cli/verb.h"

#include <iostream>

namespace probeproxy::cli {

int runCommandLine(int argc, char** argv) {
  CLI::App app{
      "probeproxy builds convex proxy volumes for parallax-corrected cubemaps from the level,\n"
      "validates authored probe volumes, measures every correction method, and exports\n"
      "proxies for the game runtime.",
      "probeproxy"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "probeproxy 0.1.0");
  // The readers' size limits (core/scene/scene_limits.h, which checks them), for every verb;
  // given before or after the verb.
  app.fallthrough();
  InputLimits limits;
  app.add_option("--max-triangles", limits.maxTriangles,
                 "Refuse a level of more triangles than this, before it fills memory")
      ->default_val(limits.maxTriangles);
  app.add_option("--max-file-mb", limits.maxFileMebibytes,
                 "Refuse a level file (or a .pk3 entry, inflated) larger than this many MiB")
      ->default_val(limits.maxFileMebibytes);

  std::vector<Verb> verbs = {addDemoVerb(app), addBuildVerb(app), addExportVerb(app),
                             addCorrectVerb(app), addValidateVerb(app)};
  verbs.push_back(addBlendVerb(app));
  verbs.push_back(addBenchVerb(app));
  verbs.push_back(addLevelInfoVerb(app));
  verbs.push_back(addSurveyVerb(app));
  verbs.push_back(addLayoutVerb(app));

  // CLI11 would only say "a subcommand is required"; name what was typed and what exists.
  std::string known;
  bool isVerb = false;
  for (const Verb& verb : verbs) {
    known += (known.empty() ? "" : ", ") + verb.command->get_name();
    isVerb = isVerb || (argc > 1 && verb.command->get_name() == argv[1]);
  }
  if (argc > 1 && argv[1][0] != '-' && !isVerb) {
    std::cerr << "probeproxy: unknown verb '" << argv[1] << "' (verbs: " << known << ")\n";
    return kExitBadInput;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "probeproxy: " << e.what() << " (see probeproxy --help)\n";
    return kExitBadInput;
  }

  try {
    setInputLimits(limits);
    for (const Verb& verb : verbs) {
      if (verb.command->parsed()) return verb.run();
    }
  } catch (const InputError& e) {
    std::cerr << "probeproxy: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "probeproxy: internal error: " << oneLine(e.what()) << "\n";
    return kExitInternalError;
  }
  return kExitBadInput;
}

}  // namespace probeproxy::cli
