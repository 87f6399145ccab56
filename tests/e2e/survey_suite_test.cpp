// survey on the suite's box rooms (corridor, tiny closet, hangar), whose proxies are exact
// boxes: the level-wide figure agrees with the per-probe mirror_floor figures, p95 under
// 0.25 degrees both ways, and the walkable floor is the room's floor.

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/level/load_level.h"
#include "geometry/scene/scene_file.h"
#include "geometry/survey/run_survey.h"
#include "geometry/survey/survey_proxies.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace probeproxy {
namespace {

const std::filesystem::path kSuite = PROBEPROXY_SUITE_DIR;

struct BoxRoomCase {
  std::string level;
  double floorSquareMeters;  // the room's floor, less what stands on it
};

void PrintTo(const BoxRoomCase& c, std::ostream* out) { *out << c.level; }

class SurveyBoxRoom : public ::testing::TestWithParam<BoxRoomCase> {};

TEST_P(SurveyBoxRoom, AgreesWithThePerProbeFigures) {
  const BoxRoomCase& c = GetParam();
  const Scene scene = readSceneFile(kSuite / c.level / (c.level + ".scene.json"));
  const LevelMesh mesh = loadLevel(scene);
  const LevelRayCaster level(mesh);
  const SurveyOptions options;
  const SurveyResult survey = runSurvey(scene, level, options);

  EXPECT_EQ(survey.scene, c.level);
  EXPECT_EQ(survey.figures.probes, scene.probes.size());
  // Grid cells straddling a wall are lost: at most a row of 0.25 m cells along each side.
  EXPECT_NEAR(survey.figures.walkableSquareMeters, c.floorSquareMeters, 0.1 * c.floorSquareMeters);
  EXPECT_EQ(survey.figures.uncoveredShare, 0.0);
  EXPECT_LT(survey.figures.p95Deg, 0.25);

  const std::vector<ProxyShape> proxies = surveyProxyShapes(scene, level, options);
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const Probe& probe = scene.probes[i];
    const std::vector<ReflectionSample> samples =
        buildReflectionSamples(level, probe, SampleSet::MirrorFloor);
    const ErrorFigures perProbe = evaluateShape(proxies[i], probe.captureMeters, samples);
    EXPECT_LT(perProbe.p95Deg, 0.25) << probe.name;
    EXPECT_EQ(perProbe.missRate, 0.0) << probe.name;
  }
}

// The hangar's two 2.6 m shipping containers (12 x 2.5 m each) have head room on top but are
// far more than a step up: the flood fill leaves their tops out, and the floor under them.
TEST(SurveyHangar, ContainerTopsAreNotWalkable) {
  const Scene scene = readSceneFile(kSuite / "hangar" / "hangar.scene.json");
  const LevelMesh mesh = loadLevel(scene);
  const LevelRayCaster level(mesh);
  std::vector<glm::dvec3> seeds;
  for (const Probe& p : scene.probes) seeds.push_back(p.captureMeters);
  const WalkableFloor floor = walkableFloor(level, seeds);
  for (const FloorCell& c : floor.cells) ASSERT_NEAR(c.pointMeters.z, 0.0, 1e-3);
  EXPECT_NEAR(floor.areaSquareMeters(), 80.0 * 50.0 - 2.0 * 12.0 * 2.5, 1e-6);
  // Seeded on a container, the fill stays on its top.
  const glm::dvec3 onTop{-24.0, 9.0, 3.5};
  const WalkableFloor top = walkableFloor(level, std::span(&onTop, 1));
  EXPECT_NEAR(top.areaSquareMeters(), 12.0 * 2.5, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Suite, SurveyBoxRoom,
                         ::testing::Values(BoxRoomCase{"corridor", 18.0 * 3.0},
                                           BoxRoomCase{"tiny_closet", 1.0 * 0.8},
                                           BoxRoomCase{"hangar", 80.0 * 50.0 - 60.0}),
                         [](const ::testing::TestParamInfo<BoxRoomCase>& p) {
                           return p.param.level;
                         });

}  // namespace
}  // namespace probeproxy
