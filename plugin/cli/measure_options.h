#pragma once
// The options that define the floor a verb measures on and the tolerance it judges by (survey,
// validate, layout): each is set in MeasureSettings only when typed, so that what the user
// leaves out comes from the scene's measured_with or the level's game
// (plugin/jobs/measure_settings.h) instead of a default that would hide them.

#include "core/scene/measure_settings.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace probeproxy::cli {

// --grid, --step-height, --head-clearance, --eye-height, --seed X,Y,Z (repeatable; `seeds`
// holds the text until parseSeeds) and, with a help text, --tolerance-deg (whose default when
// neither the user nor the scene gives one is the verb's, `toleranceDefault`).
void addMeasureOptions(CLI::App& verb, MeasureSettings& given, std::vector<std::string>& seeds,
                       const std::string& toleranceHelp = {}, double toleranceDefault = 5.0);

void parseSeeds(const std::vector<std::string>& seeds, MeasureSettings& given);

}  // namespace probeproxy::cli
