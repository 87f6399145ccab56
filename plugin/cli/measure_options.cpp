#include "plugin/cli/measure_options.h"

#include "plugin/cli/command_line_values.h"

#include <optional>

namespace probeproxy::cli {

namespace {

void addLength(CLI::App& verb, const char* name, std::optional<double>& into,
               const std::string& help) {
  verb.add_option_function<double>(
      name, [&into](double value) { into = value; }, help);
}

}  // namespace

void addMeasureOptions(CLI::App& verb, MeasureSettings& given, std::vector<std::string>& seeds,
                       const std::string& toleranceHelp, double toleranceDefault) {
  const std::string unset = " (default: the scene's measured_with, else the level's game, else ";
  addLength(verb, "--grid", given.gridSpacingMeters,
            "walkable-floor cell size, m (default: the scene's measured_with, else 0.25)");
  addLength(verb, "--step-height", given.stepHeightMeters,
            "largest height a player steps up between neighbouring cells, m" + unset +
                "0.45; a Quake 3 BSP: 0.5625)");
  addLength(verb, "--head-clearance", given.headClearanceMeters,
            "free height walkable floor needs above it, m" + unset + "1.8; a Quake 3 BSP: 1.75)");
  addLength(verb, "--eye-height", given.eyeHeightMeters,
            "the player's eyes above the floor, m" + unset + "1.7; a Quake 3 BSP: 1.5625)");
  verb.add_option("--seed", seeds,
                  "X,Y,Z (world, metres): flood-fill the walkable floor from here (repeat for "
                  "more); default: the scene's measured_with, else the level's spawn points, "
                  "else the scene's probes");
  if (!toleranceHelp.empty()) {
    addLength(verb, "--tolerance-deg", given.toleranceDeg,
              toleranceHelp + " (default: the scene's measured_with, else " +
                  CLI::detail::to_string(toleranceDefault) + ")");
  }
}

void parseSeeds(const std::vector<std::string>& seeds, MeasureSettings& given) {
  for (const std::string& seed : seeds)
    given.seedPointsMeters.push_back(parsePoint(seed, "--seed"));
}

}  // namespace probeproxy::cli
