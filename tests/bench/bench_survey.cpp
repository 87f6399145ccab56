// Survey cost (geometry/survey/run_survey.h) on a synthetic level the size of a large game map:
// a 100 x 100 x 6 m hall with a 10 x 10 grid of 1 m pillars, 16 probes on a 4 x 4 grid with
// overlapping 30 m box influences, each looked up through the hall's box. The whole survey
// (flood fill, samples, blend, figures), at two floor grids. The target: a large
// real map under 30 s on 2 cores. Report medians (the machine is shared):
//   bench_survey --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

#include "geometry/builtin/box_room.h"
#include "geometry/survey/run_survey.h"

#include <benchmark/benchmark.h>

#include <utility>

namespace probeproxy {
namespace {

constexpr float kSide = 100.0f, kHeight = 6.0f;

const LevelRayCaster& hall() {
  static const LevelMesh mesh = [] {
    LevelMesh level = boxRoom({0, 0, 0}, {kSide, kSide, kHeight}, "hall");
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) {
        const glm::vec3 lo(5.0f + 10.0f * i, 5.0f + 10.0f * j, 0.0f);
        LevelMesh pillar = boxRoom(lo, lo + glm::vec3(1.0f, 1.0f, kHeight), "pillar");
        for (glm::uvec3& t : pillar.triangles) std::swap(t.y, t.z);  // faces outwards
        appendLevelMesh(level, pillar);
      }
    return level;
  }();
  static const LevelRayCaster caster(mesh);
  return caster;
}

std::vector<SurveyProbe> probes() {
  const BoxShape room{{kSide / 2, kSide / 2, kHeight / 2},
                      {kSide / 2, kSide / 2, kHeight / 2},
                      glm::dquat(1, 0, 0, 0)};
  std::vector<SurveyProbe> out;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      // Captures between pillars (pillars stand at 5 + 10 k), mid-height.
      const glm::dvec3 capture(12.5 + 25.0 * i, 12.5 + 25.0 * j, 1.6);
      BoxInfluence b;
      b.centerMeters = {capture.x, capture.y, kHeight / 2};
      b.halfExtentsMeters = {15.0, 15.0, kHeight / 2};
      b.innerHalfExtentsMeters = {10.0, 10.0, kHeight / 2};
      out.push_back({capture, b, room});
    }
  return out;
}

void BM_SurveyLargeHall(benchmark::State& state) {
  const LevelRayCaster& level = hall();
  const std::vector<SurveyProbe> p = probes();
  SurveyOptions options;
  options.floor.gridSpacingMeters = static_cast<double>(state.range(0)) / 100.0;
  SurveyResult result;
  for (auto _ : state) {
    result = surveyProbes(p, level, options);
    // A copy: this Google Benchmark's DoNotOptimize may pass a double through a general
    // register and leave other bits in it.
    double p95 = result.figures.p95Deg;
    benchmark::DoNotOptimize(p95);
  }
  state.counters["walkable_m2"] = result.figures.walkableSquareMeters;
  state.counters["samples"] = static_cast<double>(result.figures.samples);
  state.counters["p95_deg"] = result.figures.p95Deg;
  state.counters["over_5_deg_share"] = result.figures.overToleranceShare;
}
BENCHMARK(BM_SurveyLargeHall)->Arg(50)->Arg(25)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace probeproxy

BENCHMARK_MAIN();
