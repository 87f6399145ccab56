// Mixing cost (core/blend/mix_cubemaps.h): 1 to 4 probes of 256 px with full mip chains (9
// levels, linear float RGB) mixed into one cube, every level, on one thread: the seed's table
// (PS3: 0.29, 0.40, 0.54, 0.68 ms for 1-4 cubemaps of 256 px, DXT1, GPU). Baseline in the same
// run: copying one such cube (every level) with memcpy, the memory-bandwidth floor of writing
// the result. The output is allocated once, as a runtime mixing every frame would. Also the
// blend weights at one point (4 overlapping volumes). Report medians (CPU time: the machine
// is shared):
//   bench_blend --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include "core/blend/blend_weights.h"
#include "core/blend/mix_cubemaps.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <random>
#include <vector>

namespace probeproxy {
namespace {

constexpr int kFaceSize = 256;

// A cube of fixed-seed noise with its full mip chain: synthetic, the cost does not depend on
// the values.
Cubemap noiseCube(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 4.0f);
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (auto& f : faces) {
    f.resize(static_cast<std::size_t>(kFaceSize) * kFaceSize * 3);
    for (float& v : f) v = u(rng);
  }
  Cubemap cube = Cubemap::fromFaces(kFaceSize, std::move(faces));
  cube.buildMipChain();
  return cube;
}

const std::vector<Cubemap>& probes() {
  static const std::vector<Cubemap> cubes = {noiseCube(1), noiseCube(2), noiseCube(3),
                                             noiseCube(4)};
  return cubes;
}

void BM_MixProbes256(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  std::vector<WeightedCubemap> weighted;
  for (int i = 0; i < count; ++i) weighted.push_back({&probes()[i], 1.0f / count});
  Cubemap mixed;  // allocated once, as a runtime mixing every frame would
  for (auto _ : state) {
    mixCubemapsInto(weighted, mixed);
    benchmark::DoNotOptimize(mixed.levels.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_MixProbes256)->DenseRange(1, 4)->Unit(benchmark::kMillisecond);

// The floor: one cube's every level copied into another, allocated once.
void BM_CopyOneCube256(benchmark::State& state) {
  const Cubemap& source = probes()[0];
  Cubemap copy;
  for (auto _ : state) {
    copy.levels.resize(source.levels.size());
    for (std::size_t l = 0; l < source.levels.size(); ++l) {
      copy.levels[l].faceSize = source.levels[l].faceSize;
      for (int f = 0; f < kCubeFaceCount; ++f) {
        copy.levels[l].rgb[f].resize(source.levels[l].rgb[f].size());
        std::memcpy(copy.levels[l].rgb[f].data(), source.levels[l].rgb[f].data(),
                    source.levels[l].rgb[f].size() * sizeof(float));
      }
    }
    benchmark::DoNotOptimize(copy.levels.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CopyOneCube256)->Unit(benchmark::kMillisecond);

// Weights at a point covered by four overlapping volumes, per scheme.
void BM_BlendWeights(benchmark::State& state) {
  std::vector<InfluenceVolume> volumes;
  for (int i = 0; i < 4; ++i) {
    volumes.push_back(BoxInfluence{{i * 2.0, 0, 1.5}, {4, 2, 1.5}, {1, 0, 0, 0}, {1, 1, 1}});
  }
  const BlendOptions options{state.range(0) == 0 ? BlendScheme::Lagarde : BlendScheme::Enlighten,
                             4};
  glm::dvec3 p(3.1, 0.2, 1.4);
  for (auto _ : state) {
    benchmark::DoNotOptimize(blendWeights(volumes, p, options));
    p.x = p.x > 3.3 ? 3.1 : p.x + 1e-3;
  }
}
BENCHMARK(BM_BlendWeights)->Arg(0)->Arg(1);

}  // namespace
}  // namespace probeproxy

BENCHMARK_MAIN();
