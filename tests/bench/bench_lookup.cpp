// Cubemap lookup cost per method: the seeds' scalar shader ports (one ray per call) and the
// batched SoA kernels (4096 rays per call) on the same rays, in one process, then the batched
// speed-up per method. Report medians:
//   bench_lookup --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include "core/parallax/prepared_proxy.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

constexpr std::size_t kRays = 4096;

struct Workload {
  std::string name;
  PreparedProxy proxy;
  std::vector<float> x, y, z, rx, ry, rz;  // rays from points inside the proxy
  std::vector<float> dx, dy, dz;
  std::vector<std::uint8_t> miss;
};

Workload makeWorkload(const std::string& name, const ProxyShape& shape, unsigned seed) {
  Workload w{name, prepareProxy(shape, {0.3, -0.2, 1.2}), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::normal_distribution<float> g;
  for (std::size_t i = 0; i < kRays; ++i) {
    // Inside every shape below: within 1.5 m of (0, 0, 1.2).
    w.x.push_back(1.5f * u(rng) * 0.57f), w.y.push_back(1.5f * u(rng) * 0.57f);
    w.z.push_back(1.2f + 1.5f * u(rng) * 0.57f);
    glm::vec3 r(g(rng), g(rng), g(rng));
    r = glm::normalize(r + glm::vec3(0, 0, 1e-3f));
    w.rx.push_back(r.x), w.ry.push_back(r.y), w.rz.push_back(r.z);
  }
  w.dx.resize(kRays), w.dy.resize(kRays), w.dz.resize(kRays), w.miss.resize(kRays);
  return w;
}

std::vector<Workload> workloads() {
  const glm::dquat tilt = glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 0, 1));
  ConvexProxy convex = convexFromBox(BoxShape{{0, 0, 1.5}, {5, 4, 1.5}, tilt});
  const glm::dvec3 slope = glm::normalize(glm::dvec3(1, 0.5, 1.2));
  convex.planes.push_back({slope, glm::dot(slope, glm::dvec3(2, 1, 2.2))});  // 7 planes
  std::vector<Workload> out;
  out.push_back(makeWorkload("infinite", InfiniteShape{}, 1));
  out.push_back(makeWorkload("cheap_k", CheapKShape{0.3}, 2));
  out.push_back(makeWorkload("sphere", SphereShape{{0, 0, 1.2}, {5, 4, 3}, tilt}, 3));
  out.push_back(makeWorkload("aabb", BoxShape{{0, 0, 1.5}, {5, 4, 1.5}}, 4));
  out.push_back(makeWorkload("obb", BoxShape{{0, 0, 1.5}, {5, 4, 1.5}, tilt}, 5));
  out.push_back(makeWorkload("convex", convex, 6));
  return out;
}

void scalarLookups(benchmark::State& state, Workload* w) {
  for (auto _ : state) {
    for (std::size_t i = 0; i < kRays; ++i) {
      const seed::Lookup l =
          lookupScalar(w->proxy, {w->x[i], w->y[i], w->z[i]}, {w->rx[i], w->ry[i], w->rz[i]});
      w->dx[i] = l.direction.x, w->dy[i] = l.direction.y, w->dz[i] = l.direction.z;
      w->miss[i] = l.miss;
    }
    benchmark::DoNotOptimize(w->dx.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}

void batchedLookups(benchmark::State& state, Workload* w) {
  const RaysSoA rays{w->x, w->y, w->z, w->rx, w->ry, w->rz};
  const LookupsSoA out{w->dx, w->dy, w->dz, w->miss};
  for (auto _ : state) {
    lookupBatch(w->proxy, rays, out);
    benchmark::DoNotOptimize(w->dx.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRays));
}

// The console table, plus each benchmark's median time (or its only run) kept for the
// speed-up summary.
class SpeedupReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const std::string name = run.run_name.function_name;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
        seconds[name] = run.GetAdjustedRealTime();
      else if (run.run_type == Run::RT_Iteration && !seconds.count(name))
        seconds[name] = run.GetAdjustedRealTime();
    }
  }
  std::map<std::string, double> seconds;
};

}  // namespace
}  // namespace probeproxy

int main(int argc, char** argv) {
  using namespace probeproxy;
  std::vector<Workload> ws = workloads();
  for (Workload& w : ws) {
    benchmark::RegisterBenchmark(("scalar/" + w.name).c_str(), scalarLookups, &w);
    benchmark::RegisterBenchmark(("batched/" + w.name).c_str(), batchedLookups, &w);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SpeedupReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  std::printf("\nns per lookup (median) and batched speed-up over scalar, %zu rays per call:\n",
              kRays);
  for (const Workload& w : ws) {
    const auto s = reporter.seconds.find("scalar/" + w.name);
    const auto b = reporter.seconds.find("batched/" + w.name);
    if (s == reporter.seconds.end() || b == reporter.seconds.end()) continue;
    // GetAdjustedRealTime is in the benchmark's time unit (ns by default) per iteration.
    std::printf("  %-9s scalar %7.2f ns  batched %7.2f ns  speed-up %5.1fx\n", w.name.c_str(),
                s->second / kRays, b->second / kRays, s->second / b->second);
  }
  return 0;
}
