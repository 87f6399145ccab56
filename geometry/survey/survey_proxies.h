#pragma once
// The proxy each probe of a survey is looked up through (SurveyOptions::proxies): the scene's
// (authored; `auto` built now and the kept candidate taken; or a build export's kept ones),
// none (infinite), or the `aabb` candidate a build makes.

#include "core/proxy/proxy_shape.h"
#include "core/scene/scene.h"
#include "geometry/export/runtime_export.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/survey_options.h"

#include <functional>
#include <vector>

namespace probeproxy {

// One shape per scene probe, in scene order. InputError when proxiesJson cannot be read or
// lacks a probe of the scene.
// `onProbeBuilt(done, total)` is called as `auto` probes finish building (serialized).
std::vector<ProxyShape> surveyProxyShapes(
    const Scene& scene, const LevelRayCaster& level, const SurveyOptions& options,
    const std::function<void(std::size_t, std::size_t)>& onProbeBuilt = {});

// The presets an engine model reads, one probe per scene probe in scene order: proxiesJson's
// (InputError when it lacks a probe of the scene), else every probe built now (authored ones
// too: their candidates give the box engines their boxes) and exported as `build` exports.
RuntimeExport surveyPresets(const Scene& scene, const LevelRayCaster& level,
                            const SurveyOptions& options,
                            const std::function<void(std::size_t, std::size_t)>& onProbeBuilt = {});

}  // namespace probeproxy
