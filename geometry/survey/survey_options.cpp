#include "geometry/survey/survey_options.h"

#include "core/errors/input_error.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace probeproxy {

void SurveyOptions::check() const {
  // Named as the CLI spells them, the one place a user sets them.
  auto require = [](bool ok, const char* option, const char* range, double value) {
    if (ok) return;
    char got[64];
    std::snprintf(got, sizeof got, ", got %g", value);
    throw InputError(option, std::string("must be ") + range + got);
  };
  require(blend.maxProbes >= 1 && blend.maxProbes <= 64, "--max-probes", "1 to 64",
          blend.maxProbes);
  require(std::isfinite(toleranceDeg) && toleranceDeg > 0.0 && toleranceDeg <= 180.0,
          "--tolerance-deg", "over 0 and at most 180", toleranceDeg);
  floor.check();
  for (const glm::dvec3& p : seedPointsMeters)
    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "seed points", "finite",
            p.x + p.y + p.z);
  require(samplesPerCell >= 1 && samplesPerCell <= 1024, "--samples-per-cell", "1 to 1024",
          samplesPerCell);
  require(maxSamples >= 1, "--max-samples", "at least 1", static_cast<double>(maxSamples));
  require(eyeHeightMeters > 0.0 && eyeHeightMeters < floor.headClearanceMeters, "eye height",
          "over 0 and under the head clearance", eyeHeightMeters);
  require(maxViewAttempts >= 1 && maxViewAttempts <= 1024, "view attempts", "1 to 1024",
          maxViewAttempts);
}

}  // namespace probeproxy
