#pragma once
// Each verb of the `probeproxy` CLI adds its subcommand and says what runs when it is chosen.
// The run function returns the exit code; bad input is thrown as InputError and becomes one
// line and exit code 2 in main.

#include <CLI/CLI.hpp>

#include <functional>
#include <vector>

namespace probeproxy::cli {

struct Verb {
  CLI::App* command = nullptr;
  std::function<int()> run;  // called once the command line parsed; returns the exit code
};

Verb addDemoVerb(CLI::App& app);
Verb addBuildVerb(CLI::App& app);
Verb addExportVerb(CLI::App& app);
Verb addValidateVerb(CLI::App& app);
Verb addCorrectVerb(CLI::App& app);
Verb addBlendVerb(CLI::App& app);
Verb addBenchVerb(CLI::App& app);
Verb addLevelInfoVerb(CLI::App& app);  // hidden: BSP figures and spawn points for scripts
Verb addSurveyVerb(CLI::App& app);
Verb addLayoutVerb(CLI::App& app);

}  // namespace probeproxy::cli
