// The rays from capture points to a floor's true hits, kept (geometry/survey/capture_sights.h):
// in an L-shaped room, where an arm's far end does not see all of the other arm's floor, the
// kept answers are the rays' own, one capture point shared by two probes has one id, and a
// survey that keeps its rays gives the figures of one that casts them afresh.

#include "geometry/survey/capture_sights.h"
#include "geometry/builtin/l_room.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/survey/run_survey.h"
#include "tests/unit/engine_test_probes.h"

#include <gtest/gtest.h>

namespace probeproxy {
namespace {

constexpr glm::dquat kUnturned{1, 0, 0, 0};

TEST(CaptureSights, KeepTheRaysAnswersOnceAPointAndSurveyAsTheRaysDo) {
  const LevelRayCaster level(lRoom({}));  // corner [0, 4]^2, arms to x 10 and to y 10, 3 m high
  SurveyOptions options;
  options.engine = Engine::Unity;
  options.samplesPerCell = 2;
  const std::vector<glm::dvec3> seeds = {{2.0, 2.0, 1.5}};
  const SurveyFloor floor = prepareSurveyFloor(seeds, level, options);
  ASSERT_GT(floor.samples.size(), 100u);

  const glm::dvec3 xArmEnd{9.0, 2.0, 1.5}, yArmEnd{2.0, 9.0, 1.5};
  const BoxShape xArm{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, kUnturned};
  const BoxShape yArm{{2.0, 5.0, 1.5}, {2.0, 5.0, 1.5}, kUnturned};
  const BoxShape corner{{2.0, 2.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned};
  const RuntimeExport presets = exportOf({boxProbe("x arm", xArm, xArmEnd, 0.5),
                                          boxProbe("x arm, corner box", corner, xArmEnd, 0.5),
                                          boxProbe("y arm", yArm, yArmEnd, 0.5)});
  const EngineModel model = unityModel(presets);

  CaptureSights sights(floor);
  const std::vector<std::uint32_t> ids = sights.idsOf(model.probes);
  ASSERT_EQ(ids.size(), 3u);
  EXPECT_EQ(ids[0], ids[1]);  // two boxes, one capture point
  EXPECT_NE(ids[0], ids[2]);
  EXPECT_EQ(sights.idsOf(model.probes), ids);  // ids stay

  std::size_t hidden = 0;
  for (std::size_t i = 0; i < floor.samples.size(); ++i) {
    const ReflectionSample& s = floor.samples[i].sample;
    for (const auto& [id, capture] : {std::pair{ids[0], xArmEnd}, std::pair{ids[2], yArmEnd}}) {
      const bool cast = trueHitHiddenFrom(level, capture, s);
      ASSERT_EQ(sights.hidden(level, i, id), cast) << "sample " << i;
      ASSERT_EQ(sights.hidden(level, i, id), cast) << "sample " << i << ", asked again";
      hidden += cast;
    }
  }
  EXPECT_GT(hidden, 0u);  // the L hides floor from each arm's far end

  const SurveyFigures cast = surveyModel(model, floor, level, options).figures;
  CaptureSights kept(floor);
  for (int round = 0; round < 2; ++round) {  // the second survey reads what the first cast
    const SurveyFigures f = surveyModel(model, floor, level, options, &kept).figures;
    EXPECT_EQ(f.p95Deg, cast.p95Deg);
    EXPECT_EQ(f.overToleranceShare, cast.overToleranceShare);
    EXPECT_EQ(f.occludedShare, cast.occludedShare);
    EXPECT_EQ(f.uncoveredShare, cast.uncoveredShare);
  }
  EXPECT_GT(cast.occludedShare, 0.0);
}

}  // namespace
}  // namespace probeproxy
