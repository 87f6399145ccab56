#include "geometry/survey/survey_options.h"

#include "core/errors/input_error.h"
#include "core/errors/option_checks.h"

#include <cmath>

namespace probeproxy {

void SurveyOptions::check() const {
  requireInRange("max_probes", blend.maxProbes, 1, 64);
  requireInRange("tolerance_deg", toleranceDeg, 1e-9, 180.0);
  floor.check();
  for (const glm::dvec3& p : seedPointsMeters) {
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
      throw InputError("option seed_points", "every seed point must be finite");
  }
  requireInRange("samples_per_cell", samplesPerCell, 1, 1024);
  requireInRange<std::size_t>("max_samples", maxSamples, 1, 1'000'000'000);
  requireInRange("eye_height_m", eyeHeightMeters, 1e-3, floor.headClearanceMeters);
  requireInRange("max_view_attempts", maxViewAttempts, 1, 1024);
  if (engine != Engine::Generic && proxies != SurveyProxies::Scene)
    throw InputError("option proxy",
                     "an engine model looks each probe up through the preset a build exports "
                     "for that engine: use proxy scene (or the generic engine)");
}

}  // namespace probeproxy
