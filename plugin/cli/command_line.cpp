#include "plugin/cli/command_line.h"

#include "core/errors/input_error.h"
#include "core/scene/scene_limits.h"
#include "plugin/cli/verb.h"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace probeproxy::cli {

namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The name of `names` a typo of `word` most likely meant: at most a third of it mistyped (two
// letters in a short word, a swap).
std::string closestName(std::string_view word, const std::vector<std::string>& names) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& name : names) {
    const std::size_t d = editDistance(word, name);
    if (d < bestDistance) best = name, bestDistance = d;
  }
  return best;
}

// "--toleranse-deg" -> " (did you mean --tolerance-deg?)", for the first unknown option of the
// verb given that is close to one of its options; empty when none is.
std::string optionSuggestion(const CLI::ExtrasError& error, const CLI::App& app,
                             const std::vector<Verb>& verbs) {
  const std::string text = error.what();
  std::vector<std::string> options;
  for (const Verb& verb : verbs)
    if (verb.command->parsed())
      for (const CLI::Option* option : verb.command->get_options())
        for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  for (const CLI::Option* option : app.get_options())
    for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (word.rfind("--", 0) != 0) continue;
    if (const std::string near = closestName(word, options); !near.empty())
      return " (did you mean " + near + "?)";
  }
  return {};
}

}  // namespace

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
  std::vector<std::string> shown;
  for (const Verb& verb : verbs) {
    if (!verb.command->get_group().empty()) shown.push_back(verb.command->get_name());
    isVerb = isVerb || (argc > 1 && verb.command->get_name() == argv[1]);
  }
  for (const std::string& name : shown) known += (known.empty() ? "" : ", ") + name;
  if (argc > 1 && argv[1][0] != '-' && !isVerb) {
    const std::string near = closestName(argv[1], shown);
    std::cerr << "probeproxy: unknown verb '" << argv[1] << "'"
              << (near.empty() ? "" : " (did you mean '" + near + "'?)") << "; verbs: " << known
              << "\n";
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
  } catch (const CLI::ExtrasError& e) {
    std::cerr << "probeproxy: " << e.what() << optionSuggestion(e, app, verbs)
              << " (see probeproxy --help)\n";
    return kExitBadInput;
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
