// Every job checks its own options before any work, so the CLI and the add-on refuse the same
// values with the same line; the check happens before the scene is even read.

#include "core/errors/input_error.h"
#include "plugin/jobs/bench/bench_job.h"
#include "plugin/jobs/blend/blend_job.h"
#include "plugin/jobs/build/build_job.h"
#include "plugin/jobs/correct/correct_job.h"
#include "plugin/jobs/measure_settings.h"
#include "plugin/jobs/survey/survey_job.h"
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

TEST(MeasureSettings, TheOptionOverTheSceneOverTheLevelsGameOverTheDefault) {
  Scene scene;
  scene.measuredWith.stepHeightMeters = 0.6;
  scene.measuredWith.toleranceDeg = 3.0;
  scene.measuredWith.seedPointsMeters = {{1, 2, 3}};
  LevelMesh level;
  level.gamePlayer.stepHeightMeters = 0.5625;
  level.gamePlayer.headClearanceMeters = 1.75;
  level.spawnPointsMeters = {{9, 9, 9}};
  MeasureSettings given;
  given.toleranceDeg = 7.0;

  SurveyOptions survey;
  applyMeasureSettings(resolvedMeasureSettings(given, scene, level), survey);
  EXPECT_EQ(survey.toleranceDeg, 7.0);                                       // the option
  EXPECT_EQ(survey.floor.stepHeightMeters, 0.6);                             // the scene
  EXPECT_EQ(survey.floor.headClearanceMeters, 1.75);                         // the level's game
  EXPECT_EQ(survey.eyeHeightMeters, 1.7);                                    // the default
  EXPECT_EQ(survey.floor.gridSpacingMeters, 0.25);                           // the default
  EXPECT_EQ(survey.seedPointsMeters, (std::vector<glm::dvec3>{{1, 2, 3}}));  // the scene's seeds

  scene.measuredWith = {};  // a hand-written scene: the level's spawn points and player
  applyMeasureSettings(resolvedMeasureSettings({}, scene, level), survey = {});
  EXPECT_EQ(survey.seedPointsMeters, (std::vector<glm::dvec3>{{9, 9, 9}}));
  EXPECT_EQ(survey.floor.stepHeightMeters, 0.5625);
  EXPECT_EQ(survey.toleranceDeg, 5.0);
}

TEST(MeasureSettings, ATallStepLiftsTheWallTestAboveIt) {
  // Nexuiz steps 34 units (1.0625 m): the wall test between cells must run above the step.
  MeasureSettings nexuiz;
  nexuiz.stepHeightMeters = 34.0 / 32.0;
  SurveyOptions survey;
  applyMeasureSettings(nexuiz, survey);
  EXPECT_GT(survey.floor.kneeHeightMeters, survey.floor.stepHeightMeters);
  EXPECT_LT(survey.floor.kneeHeightMeters, survey.floor.headClearanceMeters);
  EXPECT_NO_THROW(survey.check());
}

TEST(MeasureSettings, AStepAsTallAsThePlayerIsRefusedByName) {
  SurveyJobOptions o;
  o.input.file = "never_read.scene.json";
  o.given.stepHeightMeters = 2.0;  // the head clearance is 1.8
  EXPECT_EQ(inputErrorOf([&] { runSurveyJob(o); }),
            "option step_height: must be below the head clearance");
}

}  // namespace
}  // namespace probeproxy::jobs
