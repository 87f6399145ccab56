// Every job checks its own options before any work, so the CLI and the add-on refuse the same
// values with the same line; the check happens before the scene is even read.

#include "core/errors/input_error.h"
#include "plugin/jobs/bench/bench_job.h"
#include "plugin/jobs/blend/blend_job.h"
#include "plugin/jobs/build/build_job.h"
#include "plugin/jobs/correct/correct_job.h"
#include "plugin/jobs/validate/validate_job.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace probeproxy::jobs {
namespace {

std::string inputErrorOf(const std::function<void()>& work) {
  try {
    work();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(JobOptions, BuildRefusesEachOutOfRangeOptionByName) {
  const auto refused = [](const std::function<void(BuildJobOptions&)>& change) {
    BuildJobOptions o;
    o.input.file = "never_read.scene.json";  // the options are checked before the file
    change(o);
    return inputErrorOf([&] { runBuildJob(o); });
  };
  EXPECT_EQ(refused([](auto& o) { o.proxy.toleranceDeg = -1; }),
            "option tolerance_deg: -1 is not positive");
  EXPECT_EQ(refused([](auto& o) { o.proxy.maxPlanes = 3; }),
            "option max_planes: 3 is outside [4, 256]");
  EXPECT_EQ(refused([](auto& o) { o.proxy.maxMissRate = 1.5; }),
            "option max_miss_rate: 1.5 is outside [0, 1]");
  EXPECT_EQ(refused([](auto& o) { o.proxy.depthFaceSize = 4096; }),
            "option face_size: 4096 is outside [8, 2048]");
  EXPECT_EQ(refused([](auto& o) { o.proxy.samples.targetSamples = 10; }),
            "option samples: 10 is outside [64, 1000000]");
  EXPECT_EQ(refused([](auto& o) { o.threads = -2; }), "option threads: -2 is outside [0, 4096]");
  // In range, the file is what fails next.
  EXPECT_EQ(refused([](auto&) {}).rfind("never_read.scene.json: ", 0), 0u);
}

TEST(JobOptions, NotANumberIsRefused) {
  ValidateJobOptions o;
  o.validate.toleranceDeg = std::nan("");
  EXPECT_EQ(inputErrorOf([&] { runValidateJob(o); }), "option tolerance_deg: nan is not positive");
}

TEST(JobOptions, ValidateRefusesTheGridOutsideItsRange) {
  ValidateJobOptions o;
  o.validate.gridSpacingMeters = 0.0;
  EXPECT_EQ(inputErrorOf([&] { runValidateJob(o); }), "option grid: 0 is outside [0.01, 10]");
  o.validate.gridSpacingMeters = 0.25;
  o.validate.maxLeakShare = -0.5;
  EXPECT_EQ(inputErrorOf([&] { runValidateJob(o); }),
            "option max_leak_share: -0.5 is outside [0, 1]");
}

TEST(JobOptions, CorrectNeedsAFacePattern) {
  CorrectJobOptions o;
  o.outPattern = "out/corrected.exr";
  EXPECT_EQ(inputErrorOf([&] { runCorrectJob(o); }),
            "out/corrected.exr: the output pattern needs {face} (px nx py ny pz nz)");
}

TEST(JobOptions, BlendNeedsAFacePatternAndAProbeCount) {
  BlendJobOptions o;
  o.outPattern = "out/blend.exr";
  EXPECT_EQ(inputErrorOf([&] { runBlendJob(o); }),
            "out/blend.exr: output pattern has no {face} (e.g. out/blend_{face}.exr)");
  o.outPattern.clear();
  o.weightsPng = "weights.png";
  o.blend.maxProbes = 0;
  EXPECT_EQ(inputErrorOf([&] { runBlendJob(o); }), "option max_probes: 0 is outside [1, 64]");
}

TEST(JobOptions, BenchNeedsAScene) {
  BenchJobOptions o;
  EXPECT_EQ(inputErrorOf([&] { runBenchJob(o); }), "bench: no scene file given");
  o.scenes = {"a.scene.json"};
  o.bench.timing.repetitions = 0;
  EXPECT_EQ(inputErrorOf([&] { runBenchJob(o); }), "option repetitions: 0 is outside [1, 100]");
}

}  // namespace
}  // namespace probeproxy::jobs
