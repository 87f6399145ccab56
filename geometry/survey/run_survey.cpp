#include "geometry/survey/run_survey.h"

#include "core/errors/input_error.h"
#include "core/io/memory_budget.h"
#include "geometry/survey/area_percentile.h"
#include "geometry/survey/capture_sights.h"
#include "geometry/survey/floor_samples.h"
#include "geometry/survey/survey_proxies.h"
#include "geometry/survey/worst_floor.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace probeproxy {

namespace {

// Samples per cell, fewer on a floor so large the total would exceed the budget.
int samplesPerCell(const WalkableFloor& floor, const SurveyOptions& o) {
  const std::size_t cells = std::max<std::size_t>(1, floor.cells.size());
  const std::size_t fit = o.maxSamples / cells;
  return static_cast<int>(
      std::clamp<std::size_t>(fit, 1, static_cast<std::size_t>(o.samplesPerCell)));
}

SurveyCellError cellError(std::span<const SurveySampleError> errors) {
  SurveyCellError c;
  c.samples = static_cast<int>(errors.size());
  std::vector<AreaValue> visible;
  double area = 0.0;
  for (const SurveySampleError& e : errors) {
    area += e.areaSquareMeters;
    c.uncoveredShare += e.uncoveredWeight * e.areaSquareMeters;
    c.occludedShare += e.occludedWeight * e.areaSquareMeters;
    if (!std::isnan(e.errorDeg)) visible.push_back({e.errorDeg, shadedArea(e)});
  }
  if (area > 0.0) {
    c.uncoveredShare /= area;
    c.occludedShare /= area;
  }
  c.p95Deg = areaPercentile(visible, 0.95);
  c.medianDeg = areaPercentile(visible, 0.5);
  return c;
}

SurveyFigures figures(std::span<const SurveySampleError> errors, double toleranceDeg) {
  SurveyFigures f;
  f.samples = errors.size();
  std::vector<AreaValue> visible;
  double area = 0.0, over = 0.0, uncovered = 0.0, occluded = 0.0;
  for (const SurveySampleError& e : errors) {
    area += e.areaSquareMeters;
    uncovered += e.uncoveredWeight * e.areaSquareMeters;
    occluded += e.occludedWeight * e.areaSquareMeters;
    if (std::isnan(e.errorDeg)) continue;
    const double seen = shadedArea(e);
    visible.push_back({e.errorDeg, seen});
    if (e.errorDeg > toleranceDeg) over += seen;
  }
  f.walkableSquareMeters = area;
  if (area > 0.0) {
    f.overToleranceShare = over / area;
    f.uncoveredShare = uncovered / area;
    f.occludedShare = occluded / area;
  }
  f.medianDeg = areaPercentile(visible, 0.5);
  f.p95Deg = areaPercentile(visible, 0.95);
  return f;
}

// The survey of the prepared floor, each sample's error from `errorOf(index, sample)`; `probeOf`
// names the probes a sample's error weighs most (worst_floor.h).
template <typename SampleError>
SurveyResult surveyOn(const SurveyFloor& prepared, std::size_t probes, const SurveyOptions& o,
                      const SampleError& errorOf,
                      const std::function<SurveyProbeRef(int)>& probeOf) {
  const auto start = std::chrono::steady_clock::now();
  SurveyResult result;
  result.toleranceDeg = o.toleranceDeg;
  result.engine = o.engine;
  result.floor = prepared.floor;
  const std::vector<FloorSample>& samples = prepared.samples;
  std::vector<SurveySampleError> errors(samples.size());
  tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t i) {
    errors[i] = errorOf(i, samples[i].sample);
    errors[i].areaSquareMeters = samples[i].areaSquareMeters;
  });

  // Samples come cell by cell, the same count each.
  const std::size_t perCell = static_cast<std::size_t>(prepared.samplesPerCell);
  result.cells.resize(result.floor.cells.size());
  for (std::size_t c = 0; c < result.cells.size(); ++c)
    result.cells[c] = cellError(std::span(errors).subspan(c * perCell, perCell));

  result.figures = figures(errors, o.toleranceDeg);
  result.worst = worstFloor(errors, samples, result.figures.p95Deg, probeOf);
  result.figures.probes = probes;
  result.figures.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() +
      prepared.seconds;
  return result;
}

}  // namespace

std::uint64_t surveyMemoryBytes(std::size_t cells, int samplesPerCell) {
  return kProcessBytes + std::uint64_t(cells) * (kSurveyBytesPerCell +
                                                 std::uint64_t(samplesPerCell) * kBytesPerSample);
}

void requireSurveyMemory(const WalkableFloor& floor, int samplesPerCell, std::uint64_t budget) {
  const std::size_t cells = floor.cells.size();
  char needs[160];
  std::snprintf(needs, sizeof needs, "the walkable floor (%.0f m^2, %zu cells, %zu samples)",
                floor.areaSquareMeters(), cells, cells * std::size_t(samplesPerCell));
  requireMemory("survey", surveyMemoryBytes(cells, samplesPerCell), budget, needs,
                "survey a part of the level (--seed where it starts)");
}

SurveyFloor prepareSurveyFloor(std::span<const glm::dvec3> seedPointsMeters,
                               const LevelRayCaster& level, const SurveyOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  o.check();
  const std::span<const glm::dvec3> seeds =
      o.seedPointsMeters.empty() ? seedPointsMeters : std::span(o.seedPointsMeters);
  if (seeds.empty())
    throw InputError("survey", "no seed points: the scene has no probes and none were given");
  SurveyFloor prepared;
  prepared.floor = walkableFloor(level, seeds, o.floor);
  if (prepared.floor.cells.empty())
    throw InputError("survey", "no walkable floor under any of the " +
                                   std::to_string(seeds.size()) +
                                   " seed points (spawn or capture points): is the level Z-up "
                                   "and in metres, and does each seed stand over a floor?");
  FloorSampleOptions so;
  so.samplesPerCell = samplesPerCell(prepared.floor, o);
  so.eyeHeightMeters = o.eyeHeightMeters;
  so.maxViewAttempts = o.maxViewAttempts;
  so.upwardCosine = o.floor.upwardCosine;
  so.stepHeightMeters = o.floor.stepHeightMeters;
  so.seed = o.seed;
  prepared.samplesPerCell = so.samplesPerCell;
  requireSurveyMemory(prepared.floor, so.samplesPerCell, o.maxMemoryBytes);
  prepared.samples = buildFloorSamples(level, prepared.floor, so);
  prepared.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return prepared;
}

SurveyResult surveyProbes(std::span<const SurveyProbe> probes, const LevelRayCaster& level,
                          const SurveyOptions& o) {
  std::vector<glm::dvec3> captures;
  std::vector<InfluenceVolume> volumes;
  for (const SurveyProbe& p : probes) {
    captures.push_back(p.captureMeters);
    volumes.push_back(p.influence);
  }
  return surveyOn(
      prepareSurveyFloor(captures, level, o), probes.size(), o,
      [&](std::size_t, const ReflectionSample& sample) {
        return blendedSampleError(level, probes, volumes, sample, o.blend);
      },
      [&](int i) {
        return SurveyProbeRef{&probes[static_cast<std::size_t>(i)].proxy, i};
      });
}

SurveyResult surveyModel(const EngineModel& model, const SurveyFloor& prepared,
                         const LevelRayCaster& level, const SurveyOptions& o,
                         CaptureSights* sights) {
  const auto probeOf = [&](int i) {
    const EngineProbe& probe = model.probes[static_cast<std::size_t>(i)];
    return SurveyProbeRef{&probe.projection, probe.sceneProbe};
  };
  if (!sights) {
    return surveyOn(
        prepared, model.probes.size(), o,
        [&](std::size_t, const ReflectionSample& s) { return blendedSampleError(level, model, s); },
        probeOf);
  }
  const std::vector<std::uint32_t> ids = sights->idsOf(model.probes);
  return surveyOn(
      prepared, model.probes.size(), o,
      [&](std::size_t i, const ReflectionSample& s) {
        return blendedSampleError(model, s, [&](int probe) {
          return sights->hidden(level, i, ids[static_cast<std::size_t>(probe)]);
        });
      },
      probeOf);
}

SurveyResult runSurvey(const Scene& scene, const LevelRayCaster& level, const SurveyOptions& o,
                       const std::function<void(std::size_t, std::size_t)>& onProbeBuilt) {
  const auto start = std::chrono::steady_clock::now();
  o.check();
  SurveyResult result;
  if (o.engine == Engine::Generic) {
    const std::vector<ProxyShape> shapes = surveyProxyShapes(scene, level, o, onProbeBuilt);
    std::vector<SurveyProbe> probes;
    for (std::size_t i = 0; i < scene.probes.size(); ++i)
      probes.push_back({scene.probes[i].captureMeters, scene.probes[i].influence, shapes[i]});
    result = surveyProbes(probes, level, o);
  } else {
    const EngineModel model =
        engineModel(o.engine, surveyPresets(scene, level, o, onProbeBuilt), o.blend);
    std::vector<glm::dvec3> captures;
    for (const Probe& p : scene.probes) captures.push_back(p.captureMeters);
    result = surveyModel(model, prepareSurveyFloor(captures, level, o), level, o);
  }
  result.scene = scene.file.empty() ? std::string("scene") : scene.file.stem().stem().string();
  result.figures.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace probeproxy
