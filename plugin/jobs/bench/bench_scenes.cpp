#include "plugin/jobs/bench/bench_scenes.h"

#include "geometry/level/load_level.h"
#include "geometry/mirror_view/mirror_view_reconstruction.h"
#include "geometry/mirror_view/radiance_lookups.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/scene/scene_file.h"
#include "plugin/cost/instructions_per_lookup.h"
#include "plugin/jobs/bench/image_reference.h"
#include "plugin/jobs/bench/mixing_pointcloud_rows.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

namespace probeproxy::jobs {

namespace {

std::string sceneName(const std::string& file) {
  std::string name = std::filesystem::path(file).filename().string();
  const std::string suffix = ".scene.json";
  if (name.size() > suffix.size() && name.ends_with(suffix))
    name.resize(name.size() - suffix.size());
  return name;
}

// The shading points and reflection directions of the probe's mirror_floor samples, rounded
// to float as a shader gets them: the rays every candidate is timed on.
LookupRays raysOf(const std::vector<ReflectionSample>& samples) {
  LookupRays rays;
  for (const ReflectionSample& s : samples) {
    rays.x.push_back(float(s.xMeters.x)), rays.y.push_back(float(s.xMeters.y));
    rays.z.push_back(float(s.xMeters.z));
    rays.dirX.push_back(float(s.reflected.x)), rays.dirY.push_back(float(s.reflected.y));
    rays.dirZ.push_back(float(s.reflected.z));
  }
  return rays;
}

// Instructions per lookup of the batched kernel, counted by callgrind on the cost workload of
// the same method and plane count (the kernels are branch-free, so the count depends on these
// alone). One count per distinct workload; the workloads are split into one valgrind run per
// core (valgrind's start-up is most of a run), the runs in parallel.
std::map<std::string, std::optional<double>> countInstructions(
    const std::vector<std::string>& workloads, const std::function<void(std::string)>& say) {
  const std::size_t runs =
      std::min<std::size_t>(workloads.size(), std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::vector<std::string>> chunks(runs);
  for (std::size_t i = 0; i < workloads.size(); ++i) chunks[i % runs].push_back(workloads[i]);
  std::vector<std::vector<std::optional<double>>> counts(runs);
  std::vector<std::string> failures(runs);
  tbb::parallel_for(std::size_t(0), runs, [&](std::size_t r) {
    try {
      counts[r] = instructionsPerLookup(chunks[r], LookupPath::Batched, 1024);
    } catch (const std::exception& e) {
      failures[r] = e.what();  // not measured: null in the report, said on stderr
    }
  });
  std::map<std::string, std::optional<double>> byName;
  for (std::size_t r = 0; r < runs; ++r) {
    if (!failures[r].empty()) say("instructions per lookup not measured: " + failures[r]);
    for (std::size_t i = 0; i < chunks[r].size(); ++i)
      byName[chunks[r][i]] = counts[r].empty() ? std::nullopt : counts[r][i];
  }
  return byName;
}

// Mean PSNR over the probe's mirror views of the reflection rebuilt with this proxy; with a
// folder, the same reconstructions are written there as the pictures a person opens to see
// where the proxy goes wrong (mirror_view_reconstruction.h).
std::optional<double> psnrDb(const ImageReference& ref, const ProxyCandidate& candidate,
                             glm::dvec3 captureMeters, const std::filesystem::path& picturesIn) {
  const RadianceLookup lookup = proxyRadianceLookup(ref.cube, candidate.shape, captureMeters);
  return meanPsnrDb(
      ref.views, [&](const MirrorViewReference&) { return lookup; },
      [&](const MirrorViewReference& view, const MirrorViewReconstruction& reconstruction) {
        if (!picturesIn.empty())
          writeMirrorViewImages(picturesIn, view.view.name + "_" + candidateName(candidate), view,
                                reconstruction);
      });
}

struct LoadedScene {
  std::string name;
  Scene scene;
  std::unique_ptr<LevelRayCaster> level;
};

}  // namespace

std::vector<BenchResult> benchScenes(const std::vector<std::string>& sceneFiles,
                                     const BenchOptions& options,
                                     const std::function<void(std::string_view)>& progress) {
  const auto say = [&](const std::string& line) {
    if (progress) progress(line);
  };
  ProxyBuildOptions buildOptions = options.proxy;
  buildOptions.regenerate = true;

  // Bad input anywhere stops the bench before any work, so no partial report is written.
  std::vector<LoadedScene> scenes;
  for (const std::string& file : sceneFiles) {
    LoadedScene loaded{sceneName(file), readSceneFile(file), nullptr};
    loaded.level = std::make_unique<LevelRayCaster>(loadLevel(loaded.scene));
    checkCapturePoints(loaded.scene, *loaded.level);
    scenes.push_back(std::move(loaded));
  }

  std::vector<BenchResult> results;
  // Owned here so the timing jobs can point at them until the end.
  std::vector<std::unique_ptr<PreparedProxy>> prepared;
  std::vector<std::unique_ptr<LookupRays>> rays;
  std::vector<TimingJob> jobs;
  std::vector<std::size_t> jobRow;
  std::vector<std::string> jobWorkload;  // the cost workload of the job's method and planes
  std::vector<CallJob> calls;            // mixing step and point cloud: ns per texel or point
  std::vector<std::size_t> callRow;
  std::vector<std::unique_ptr<std::vector<ReflectionSample>>> draws;
  std::map<std::string, std::optional<double>> instructions;
  for (const LoadedScene& s : scenes) {
    say("building proxies: " + s.name + " (" + std::to_string(s.scene.probes.size()) + " probes)");
    const std::vector<ProbeProxyBuild> builds = buildSceneProxies(s.scene, *s.level, buildOptions);
    for (std::size_t p = 0; p < builds.size(); ++p) {
      const Probe& probe = s.scene.probes[p];
      // The draw the build reports its errors on (build_probe_proxy.cpp: seed + 1000).
      ReflectionSampleOptions drawOptions = buildOptions.samples;
      drawOptions.seed = buildOptions.samples.seed + 1000;
      draws.push_back(std::make_unique<std::vector<ReflectionSample>>(
          buildReflectionSamples(*s.level, probe, SampleSet::MirrorFloor, drawOptions)));
      rays.push_back(std::make_unique<LookupRays>(raysOf(*draws.back())));
      std::shared_ptr<const ImageReference> images;
      if (std::optional<ImageReference> loaded = imageReference(s.scene, probe))
        images = std::make_shared<const ImageReference>(std::move(*loaded));
      for (std::size_t c = 0; c < builds[p].candidates.size(); ++c) {
        const ProxyCandidate& candidate = builds[p].candidates[c];
        BenchResult row;
        row.scene = s.name;
        row.probe = builds[p].probe;
        row.candidate = candidateName(candidate);
        row.method = std::string(methodId(candidate.shape));
        row.planes = planeCount(candidate.shape);
        row.kept = c == builds[p].kept;
        row.error = candidate.error;
        if (images) {
          try {
            const bool pictured = !options.imagesFolder.empty() &&
                                  (row.kept || candidate.origin == CandidateOrigin::Infinite ||
                                   candidate.origin == CandidateOrigin::Authored);
            row.psnrDb = psnrDb(*images, candidate, probe.captureMeters,
                                pictured ? options.imagesFolder / s.name : "");
          } catch (const std::invalid_argument&) {
            // a degenerate fit no shader could run: no image either
          }
        }
        results.push_back(std::move(row));
        if (rays.back()->size() == 0) continue;
        try {
          prepared.push_back(
              std::make_unique<PreparedProxy>(prepareProxy(candidate.shape, probe.captureMeters)));
        } catch (const std::invalid_argument&) {
          continue;  // a degenerate fit no shader could run: its cost stays null
        }
        jobs.push_back({prepared.back().get(), rays.back().get()});
        jobRow.push_back(results.size() - 1);
        jobWorkload.push_back(costWorkloadName(prepared.back()->method, row.planes));
        instructions[jobWorkload.back()] = std::nullopt;
      }
      const ProbeBenchInputs inputs{s.name,
                                    &probe,
                                    s.level.get(),
                                    &builds[p].candidates[builds[p].kept],
                                    *draws.back(),
                                    images,
                                    buildOptions.depthFaceSize};
      for (auto rowsOf : {mixingRows, pointCloudRows}) {
        for (MethodRow& m : rowsOf(inputs)) {
          results.push_back(std::move(m.row));
          if (!m.cost) continue;
          calls.push_back(std::move(*m.cost));
          callRow.push_back(results.size() - 1);
        }
      }
    }
  }

  if (options.countInstructions) {
    std::vector<std::string> workloads;
    for (const auto& [name, count] : instructions) workloads.push_back(name);
    say("counting instructions per lookup (callgrind): " + std::to_string(workloads.size()) +
        " workloads");
    instructions = countInstructions(workloads, say);
  }
  say("timing " + std::to_string(jobs.size()) + " proxies, scalar and batched, and " +
      std::to_string(calls.size()) + " corrected cubemaps and point clouds, " +
      std::to_string(options.timing.repetitions) + " repetitions");
  const Timings timings =
      timeBenchmarks(jobs, calls, options.timing, [&](std::size_t done, std::size_t total) {
        if (done * 10 / total != (done - 1) * 10 / total)
          say("timed " + std::to_string(done) + "/" + std::to_string(total) + " benchmarks");
      });
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    results[jobRow[j]].nsPerLookup = timings.lookups[j].batchedNs;
    results[jobRow[j]].nsPerLookupScalar = timings.lookups[j].scalarNs;
    results[jobRow[j]].instructionsPerLookup = instructions[jobWorkload[j]];
  }
  for (std::size_t c = 0; c < calls.size(); ++c)
    results[callRow[c]].nsPerLookup = timings.nsPerItem[c];
  return results;
}

}  // namespace probeproxy::jobs
