// Milliseconds per corrected cubemap (docs/methods_and_measures.md "Measures", cost): the mixing
// step of Lagarde & Zanuttini 2012 for one camera, per texel (mixing_plane) against rasterized
// (raster_convex), on a box proxy and on a 20-plane convex proxy, every mip level of a --face-size
// (default 128) source cube. One thread.
//
//   build/tests/bench/bench_mixing --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true

#include "core/mixing/corrected_cubemap.h"
#include "core/mixing/reflected_camera.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/builtin/twenty_plane_proxy.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

// A smooth, non-constant source so sampling does real work: each texel's direction as colour.
Cubemap sourceCube(int n) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f)
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) {
        const glm::vec3 d = texelDirection(static_cast<CubeFace>(f), col, row, n);
        for (int c = 0; c < 3; ++c) faces[f].push_back(0.5f + 0.5f * d[c]);
      }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  return cube;
}

struct Workload {
  Cubemap source;
  ConvexProxy proxy;
  glm::dvec3 capture{0.5, 0.3, 1.4};
  glm::dvec3 reflectedCamera{0.0};
};

void correct(benchmark::State& state, const Workload* w, MixingMethod method) {
  std::size_t texels = 0;
  for (const CubemapLevel& level : w->source.levels)
    texels += static_cast<std::size_t>(kCubeFaceCount) * level.faceSize * level.faceSize;
  for (auto _ : state) {
    CorrectedCubemap out =
        correctCubemap(w->source, w->capture, w->proxy, w->reflectedCamera, method);
    benchmark::DoNotOptimize(out.cube.levels.data());
  }
  state.counters["texels"] = static_cast<double>(texels);
  state.counters["planes"] = static_cast<double>(w->proxy.planes.size());
}

}  // namespace
}  // namespace probeproxy

int main(int argc, char** argv) {
  using namespace probeproxy;
  int faceSize = 128;
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--face-size") == 0 && i + 1 < argc) {
      faceSize = std::atoi(argv[++i]);
    } else {
      rest.push_back(argv[i]);
    }
  }
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());

  // The analytic box room (6 x 4 x 3 m, floor z = 0), a camera over its mirror floor.
  const ReflectionPlane floor{{0, 0, 0}, {0, 0, 1}};
  const glm::dvec3 reflected = reflectThroughPlane({1.1, -0.7, 1.7}, floor);
  static Workload box{sourceCube(faceSize),
                      convexFromBox({{0, 0, 1.5}, {3, 2, 1.5}, {1, 0, 0, 0}}),
                      {0.5, 0.3, 1.4},
                      reflected};
  static Workload convex{
      box.source, twentyPlaneProxy({0.0, 0.0, 1.5}, {3.5, 2.5, 1.8}), {0.5, 0.3, 1.4}, reflected};
  const std::string suffix = "/" + std::to_string(faceSize) + "px_mips";
  for (auto [name, w] : {std::pair{"box", &box}, std::pair{"convex20", &convex}}) {
    benchmark::RegisterBenchmark(("mixing_plane/" + std::string(name) + suffix).c_str(), correct, w,
                                 MixingMethod::MixingPlane)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("raster_convex/" + std::string(name) + suffix).c_str(), correct,
                                 w, MixingMethod::RasterConvex)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
