#include "geometry/survey/survey_options.h"

#include "core/errors/input_error.h"

#include <cmath>
#include <string>

namespace probeproxy {

void SurveyOptions::check() const {
  auto require = [](bool ok, const std::string& option, const std::string& what) {
    if (!ok) throw InputError(option, what);
  };
  require(blend.maxProbes >= 1 && blend.maxProbes <= 64, "--max-probes", "must be 1 to 64");
  require(std::isfinite(toleranceDeg) && toleranceDeg > 0.0 && toleranceDeg <= 180.0,
          "--tolerance-deg", "must be over 0 and at most 180, got " + std::to_string(toleranceDeg));
  floor.check();
  for (const glm::dvec3& p : seedPointsMeters)
    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "seed points",
            "must be finite");
  require(samplesPerCell >= 1 && samplesPerCell <= 1024, "--samples-per-cell",
          "must be 1 to 1024, got " + std::to_string(samplesPerCell));
  require(maxSamples >= 1, "--max-samples", "must be at least 1");
  require(eyeHeightMeters > 0.0 && eyeHeightMeters < floor.headClearanceMeters, "--eye-height",
          "must be over 0 and under the head clearance");
  require(maxViewAttempts >= 1 && maxViewAttempts <= 1024, "view attempts", "must be 1 to 1024");
}

}  // namespace probeproxy
