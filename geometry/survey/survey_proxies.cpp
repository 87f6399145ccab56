#include "geometry/survey/survey_proxies.h"

#include "core/errors/input_error.h"
#include "geometry/export/runtime_probe_shape.h"
#include "geometry/probe_proxies/authored_proxy_shape.h"
#include "geometry/probe_proxies/build_scene_proxies.h"

#include <optional>

namespace probeproxy {

namespace {

// The export's probes in scene order.
RuntimeExport exportInSceneOrder(const Scene& scene, const std::filesystem::path& file) {
  RuntimeExport runtime = readRuntimeExport(file);
  std::vector<RuntimeProbe> ordered;
  for (const Probe& probe : scene.probes) {
    const RuntimeProbe* found = nullptr;
    for (const RuntimeProbe& p : runtime.probes)
      if (p.name == probe.name) found = &p;
    if (!found) throw InputError(file, "no probe named '" + probe.name + "' (the scene has it)");
    ordered.push_back(*found);
  }
  runtime.probes = std::move(ordered);
  return runtime;
}

std::vector<ProxyShape> fromExport(const Scene& scene, const std::filesystem::path& file) {
  std::vector<ProxyShape> shapes;
  for (const RuntimeProbe& p : exportInSceneOrder(scene, file).probes)
    shapes.push_back(runtimeProbeShape(p, file));
  return shapes;
}

// Builds only the probes that need it (`auto`, or all for BestAabb): builds are the slow part.
std::vector<ProxyShape> fromBuilds(
    const Scene& scene, const LevelRayCaster& level, const SurveyOptions& o,
    const std::function<void(std::size_t, std::size_t)>& onProbeBuilt) {
  const bool aabb = o.proxies == SurveyProxies::BestAabb;
  std::vector<std::optional<ProxyShape>> shapes(scene.probes.size());
  Scene toBuild = scene;
  toBuild.probes.clear();
  std::vector<std::size_t> built;
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    if (!aabb) shapes[i] = authoredProxyShape(scene.probes[i].proxy, scene);
    if (shapes[i]) continue;
    toBuild.probes.push_back(scene.probes[i]);
    built.push_back(i);
  }
  ProxyBuildOptions buildOptions = o.build;
  if (aabb) buildOptions.regenerate = true;
  const std::vector<ProbeProxyBuild> builds =
      buildSceneProxies(toBuild, level, buildOptions, onProbeBuilt);
  for (std::size_t b = 0; b < builds.size(); ++b) {
    const ProbeProxyBuild& build = builds[b];
    const ProxyCandidate* pick = &build.candidates.at(build.kept);
    if (aabb) {
      // The box an engine's box projection would get: the best-scoring `aabb` candidate.
      const ProxyCandidate* best = nullptr;
      for (const ProxyCandidate& c : build.candidates)
        if (c.origin == CandidateOrigin::Aabb && (!best || c.error.p95Deg < best->error.p95Deg))
          best = &c;
      if (best) pick = best;
    }
    shapes[built[b]] = pick->shape;
  }
  std::vector<ProxyShape> out;
  for (auto& s : shapes) out.push_back(std::move(*s));
  return out;
}

}  // namespace

RuntimeExport surveyPresets(const Scene& scene, const LevelRayCaster& level, const SurveyOptions& o,
                            const std::function<void(std::size_t, std::size_t)>& onProbeBuilt) {
  if (!o.proxiesJson.empty()) return exportInSceneOrder(scene, o.proxiesJson);
  return makeRuntimeExport(scene, buildSceneProxies(scene, level, o.build, onProbeBuilt));
}

std::vector<ProxyShape> surveyProxyShapes(
    const Scene& scene, const LevelRayCaster& level, const SurveyOptions& o,
    const std::function<void(std::size_t, std::size_t)>& onProbeBuilt) {
  if (o.proxies == SurveyProxies::Infinite)
    return std::vector<ProxyShape>(scene.probes.size(), InfiniteShape{});
  if (o.proxies == SurveyProxies::Scene && !o.proxiesJson.empty())
    return fromExport(scene, o.proxiesJson);
  return fromBuilds(scene, level, o, onProbeBuilt);
}

}  // namespace probeproxy
