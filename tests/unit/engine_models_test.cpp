// Engine models (geometry/engines/): each engine's weights at crafted points against the
// engine's formula written out from its shader, the order it composes probes in, what its
// fallback gets, and its lookups against a box room's exact answers.

#include "core/errors/input_error.h"
#include "geometry/builtin/box_room.h"
#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/survey/blended_error.h"
#include "tests/unit/engine_test_probes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace probeproxy {
namespace {

constexpr glm::dquat kUnturned{1, 0, 0, 0};

// A box influence with a 1 m fade on every axis inside `box`.
BoxInfluence fadingInside(const BoxShape& box) {
  BoxInfluence b;
  b.centerMeters = box.centerMeters;
  b.halfExtentsMeters = box.halfExtentsMeters;
  b.worldFromBox = box.worldFromBox;
  b.innerHalfExtentsMeters = box.halfExtentsMeters - 1.0;
  return b;
}

// One probe whose box, influence and capture point are the box's centre.
RuntimeExport oneProbe(const BoxShape& box) {
  return exportOf({probeWithPresets("a", box, box.centerMeters, fadingInside(box))});
}

std::map<int, double> weightsOf(const EngineBlend& b) {
  std::map<int, double> m;
  for (const EngineWeight& w : b.weights) m[w.probe] = w.weight;
  return m;
}

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

const BoxShape kBox{{2.0, 2.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned};  // [0, 4]^2 x [0, 3]
const glm::dvec3 kEye{-5.0, 2.0, 1.7};

TEST(BlendComposition, FadeSumsAverageAsTheNormalizedBlendWithProbesAddedAndTakenAway) {
  // Five probes: seen (one a miss), hidden, and one whose cubemap stops short.
  const std::vector<ProbeFade> fades = {{0, 0.5}, {1, 0.8}, {2, 0.3}, {3, 0.25}, {4, 0.6}};
  const std::vector<ProbeSight> sights = {{true, false, 2.0},
                                          {true, false, 30.0},
                                          {true, true, 1.0},
                                          {false, false, 4.0},
                                          {true, false, std::nan("")}};
  const auto direct = [&](const std::vector<int>& probes) {
    std::vector<ProbeFade> some;
    for (const int p : probes) some.push_back(fades[static_cast<std::size_t>(p)]);
    const EngineBlend b = normalizedFades(some);
    return sampleErrorOfBlend(b.weights, b.fallbackWeight,
                              [&](int p) { return sights[static_cast<std::size_t>(p)]; });
  };
  FadeSums sums;
  for (int p = 0; p < 5; ++p) sums.add(fades[p].fade, sights[p], +1);
  const auto expectSame = [](const SurveySampleError& a, const SurveySampleError& b) {
    EXPECT_EQ(a.uncovered, b.uncovered);
    EXPECT_NEAR(a.uncoveredWeight, b.uncoveredWeight, 1e-12);
    EXPECT_NEAR(a.occludedWeight, b.occludedWeight, 1e-12);
    EXPECT_EQ(std::isnan(a.errorDeg), std::isnan(b.errorDeg));
    if (!std::isnan(a.errorDeg)) {
      EXPECT_NEAR(a.errorDeg, b.errorDeg, 1e-12);
    }
  };
  expectSame(sums.averaged(), direct({0, 1, 2, 3, 4}));
  // (0.5 * 2 + 0.8 * 30 + 0.6 * 180) / 1.9 over the seen, 0.3 of 2.45 hidden, 0.25 uncaptured.
  EXPECT_NEAR(sums.averaged().errorDeg, (1.0 + 24.0 + 108.0) / 1.9, 1e-12);
  sums.add(fades[1].fade, sights[1], -1);
  expectSame(sums.averaged(), direct({0, 2, 3, 4}));
  for (const int p : {0, 4}) sums.add(fades[p].fade, sights[p], -1);
  expectSame(sums.averaged(), direct({2, 3}));  // none seen: the hidden share is the rest
  EXPECT_TRUE(std::isnan(sums.averaged().errorDeg));
  for (const int p : {2, 3}) sums.add(fades[p].fade, sights[p], -1);
  expectSame(sums.averaged(), direct({}));  // none at all: the sky
  EXPECT_TRUE(sums.averaged().uncovered);
}

TEST(BlendComposition, EachOrderAgainstItsShaderLoopWrittenOut) {
  const std::vector<ProbeFade> fades = {{0, 0.5}, {1, 0.8}, {2, 0.3}};
  // Front to back: 0.5; 0.8 of the 0.5 left; 0.3 of the 0.1 left; sky 0.07.
  EngineBlend b = frontToBack(fades);
  std::map<int, double> w = weightsOf(b);
  EXPECT_NEAR(w[0], 0.5, 1e-15);
  EXPECT_NEAR(w[1], 0.4, 1e-15);
  EXPECT_NEAR(w[2], 0.03, 1e-15);
  EXPECT_NEAR(b.fallbackWeight, 0.07, 1e-15);
  // Fill to one: 0.5, then min(0.8, 0.5), then nothing; no sky.
  b = fillToOne(fades);
  EXPECT_EQ(weightsOf(b), (std::map<int, double>{{0, 0.5}, {1, 0.5}}));
  EXPECT_EQ(b.fallbackWeight, 0.0);
  // Stopping at 0.999: 0.9995 is full, and the sky gets nothing either.
  b = fillToOne(std::vector<ProbeFade>{{0, 0.9995}, {1, 1.0}}, 0.999);
  EXPECT_EQ(weightsOf(b), (std::map<int, double>{{0, 0.9995}}));
  EXPECT_EQ(b.fallbackWeight, 0.0);
  // Up to the largest fade: 0.5, then 0.8 - 0.5, then max(0, 0.3 - 0.8) = 0; sky 1 - 0.8.
  b = upToLargestFade(fades);
  ASSERT_EQ(b.weights.size(), 2u);
  EXPECT_EQ(b.weights[0].weight, 0.5);
  EXPECT_NEAR(b.weights[1].weight, 0.3, 1e-15);
  EXPECT_NEAR(b.fallbackWeight, 0.2, 1e-15);
  // Normalized: fade over the sum 1.6; no sky unless every fade is 0.
  b = normalizedFades(fades);
  EXPECT_NEAR(weightsOf(b)[1], 0.5, 1e-15);
  EXPECT_EQ(b.fallbackWeight, 0.0);
  EXPECT_EQ(normalizedFades(std::vector<ProbeFade>{{0, 0.0}}).fallbackWeight, 1.0);
}

TEST(EngineNames, EveryNameRoundTripsAndAnUnknownOneIsRefusedWithTheList) {
  for (const Engine e : kEngines) EXPECT_EQ(engineFromName(engineName(e)), e);
  EXPECT_EQ(parseEngine("unity-hdrp"), Engine::UnityHdrp);
  try {
    parseEngine("godot");
    FAIL() << "godot is not an engine name";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--engine: expected one of generic, unity, unity-hdrp, unreal, godot3, godot4, "
              "bevy, eevee, got 'godot'");
  }
}

TEST(UnityModel, TheExportedBoxFadesOutToTheMeasuredBoxSmallerBoxOnTop) {
  // blendDistance = the 1 m fade, at most half the shortest half-extent (1.5 m): 0.75 m; the
  // exported box is [0, 4]^2 x [0, 3] shrunk by it but at the bottom: [0.75, 3.25]^2 x [0, 2.25].
  const RuntimeExport presets = oneProbe(kBox);
  ASSERT_EQ(presets.probes[0].engines.unity->blendDistance, 0.75);
  const EngineModel model = unityModel(presets);
  EXPECT_EQ(weightsOf(model.blend({2, 2, 1}, kEye)), (std::map<int, double>{{0, 1.0}}));
  // Internal-DeferredReflections: falloff = saturate(1 - |distance to the box| / 0.75 m).
  const EngineBlend half = model.blend({3.625, 2, 1.5}, kEye);
  EXPECT_NEAR(weightsOf(half)[0], 0.5, 1e-12);
  EXPECT_NEAR(half.fallbackWeight, 0.5, 1e-12);
  EXPECT_EQ(model.blend({4.0, 2, 1.5}, kEye).fallbackWeight, 1.0);  // the measured box's face
  // A small box inside the large one is drawn later, over it (its blendDistance 0.25 m): inside
  // it, it alone; 0.125 m outside it, half of it over half of the large one.
  const BoxShape small{{1.5, 1.5, 1.5}, {0.5, 0.5, 1.5}, kUnturned};
  const EngineModel nested = unityModel(
      exportOf({probeWithPresets("large", kBox, kBox.centerMeters, fadingInside(kBox)),
                probeWithPresets("small", small, small.centerMeters, fadingInside(small))}));
  EXPECT_EQ(weightsOf(nested.blend({1.5, 1.5, 1}, kEye)), (std::map<int, double>{{1, 1.0}}));
  const std::map<int, double> seam = weightsOf(nested.blend({1.875, 1.5, 1}, kEye));
  EXPECT_NEAR(seam.at(1), 0.5, 1e-12);
  EXPECT_NEAR(seam.at(0), 0.5, 1e-12);
}

TEST(UnityModel, TheMoreImportantProbeIsDrawnOverTheSmallerBox) {
  // ReflectionProbe.importance: inside both, only the important one; leaving its box, it fades
  // over the other. The large box raised to 2 now covers the small one inside it.
  const BoxShape small{{1.5, 1.5, 1.5}, {0.5, 0.5, 1.5}, kUnturned};
  RuntimeExport presets =
      exportOf({probeWithPresets("large", kBox, kBox.centerMeters, fadingInside(kBox)),
                probeWithPresets("small", small, small.centerMeters, fadingInside(small))});
  presets.probes[0].engines.unity->importance = 2;
  const EngineModel raised = unityModel(presets);
  EXPECT_EQ(weightsOf(raised.blend({1.5, 1.5, 1}, kEye)), (std::map<int, double>{{0, 1.0}}));
  // Half way out of the large box's fade (0.375 m outside its 0.75 m blend), where the small box
  // is far: the large one at half, the sky the rest.
  const EngineBlend edge = raised.blend({3.625, 2, 1.5}, kEye);
  EXPECT_EQ(weightsOf(edge), (std::map<int, double>{{0, 0.5}}));
  EXPECT_NEAR(edge.fallbackWeight, 0.5, 1e-12);
  // Both raised: the smaller box on top again.
  presets.probes[1].engines.unity->importance = 2;
  EXPECT_EQ(weightsOf(unityModel(presets).blend({1.5, 1.5, 1}, kEye)),
            (std::map<int, double>{{1, 1.0}}));
}

TEST(UnityModel, ProjectsOnTheExportedBoxGrownByTheBlendDistanceTheMeasuredBox) {
  const EngineModel model = unityModel(oneProbe(kBox));
  // From (2, 2, 1) along +x the grown box's face is x = 4: lookup (4, 2, 1) - (2, 2, 1.5).
  const std::optional<glm::dvec3> d = engineLookup(model.probes[0], {2, 2, 1}, {1, 0, 0});
  ASSERT_TRUE(d);
  EXPECT_NEAR(glm::distance(*d, glm::dvec3(2.0, 0.0, -0.5)), 0.0, 1e-12);
}

TEST(UnityHdrpModel, FadesLinearlyInsideEachFaceAndSmallerInfluenceFillsFirst) {
  const EngineModel model = unityHdrpModel(oneProbe(kBox));
  // InfluenceBoxWeight: min over faces of distance / blend distance; at x = 3.5 the +x face is
  // 0.5 m away with a 1 m blend: 0.5; the sky the rest.
  const EngineBlend b = model.blend({3.5, 2, 1.5}, kEye);
  EXPECT_NEAR(weightsOf(b)[0], 0.5, 1e-12);
  EXPECT_NEAR(b.fallbackWeight, 0.5, 1e-12);
  const BoxShape small{{3.0, 2.0, 1.5}, {1.0, 2.0, 1.5}, kUnturned};
  BoxInfluence smallInfluence = fadingInside(small);
  smallInfluence.innerHalfExtentsMeters = {0.5, 1.0, 1.0};
  const EngineModel two = unityHdrpModel(
      exportOf({probeWithPresets("large", kBox, kBox.centerMeters, fadingInside(kBox)),
                probeWithPresets("small", small, small.centerMeters, smallInfluence)}));
  // At x = 2.25: the small volume's -x face is 0.25 m away, blend 0.5: 0.5, first; the large
  // one's weight 1 is cut to the 0.5 left.
  const std::map<int, double> w = weightsOf(two.blend({2.25, 2, 1.5}, kEye));
  EXPECT_NEAR(w.at(1), 0.5, 1e-12);
  EXPECT_NEAR(w.at(0), 0.5, 1e-12);
  ASSERT_EQ(two.blend({2.25, 2, 1.5}, kEye).weights.front().probe, 1);
}

TEST(UnrealModel, SmoothstepOverSevenTenthsOfTheTransitionFromTheShrunkBox) {
  const EngineModel model = unrealModel(oneProbe(kBox));  // T = 1 m (the smallest fade)
  EXPECT_EQ(weightsOf(model.blend({3.4, 2, 1.5}, kEye)), (std::map<int, double>{{0, 1.0}}));
  // On the +x face: 0.5 m from the box shrunk by T / 2; alpha 1 - smoothstep(0, 0.7, 0.5).
  const EngineBlend face = model.blend({4.0, 2, 1.5}, kEye);
  EXPECT_NEAR(weightsOf(face)[0], 1.0 - smoothstep(0.0, 0.7, 0.5), 1e-12);
  EXPECT_NEAR(weightsOf(face)[0], 0.1982507, 1e-6);
  EXPECT_NEAR(face.fallbackWeight, smoothstep(0.0, 0.7, 0.5), 1e-12);
  EXPECT_TRUE(model.blend({4.2, 2, 1.5}, kEye).weights.empty());  // 0.2 T outside: nothing
  // Front to back, the smaller capture first.
  const BoxShape small{{3.0, 2.0, 1.5}, {1.0, 2.0, 1.5}, kUnturned};
  const EngineModel two = unrealModel(
      exportOf({probeWithPresets("large", kBox, kBox.centerMeters, fadingInside(kBox)),
                probeWithPresets("small", small, small.centerMeters, fadingInside(small))}));
  const EngineBlend b = two.blend({2.0, 2, 1.5}, kEye);  // the small one's -x face
  const double alpha = 1.0 - smoothstep(0.0, 0.7, 0.5);
  ASSERT_EQ(b.weights.size(), 2u);
  EXPECT_EQ(b.weights[0].probe, 1);
  EXPECT_NEAR(b.weights[0].weight, alpha, 1e-12);
  EXPECT_NEAR(b.weights[1].weight, 1.0 - alpha, 1e-12);
}

TEST(Godot3Model, TheRoundedCurveNormalizedOverEveryBoxHoldingThePoint) {
  // blend = max(inner); blend = mix(length(inner), blend, blend); squared; 1 - that.
  const auto curve = [](glm::dvec3 inner) {
    double b = std::max({inner.x, inner.y, inner.z});
    b = glm::length(inner) * (1.0 - b) + b * b;
    return std::max(0.0, 1.0 - b * b);
  };
  const BoxShape right{{3.0, 2.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned};
  const EngineModel model = godot3Model(
      exportOf({probeWithPresets("a", kBox, kBox.centerMeters, fadingInside(kBox)),
                probeWithPresets("b", right, right.centerMeters, fadingInside(right))}));
  const glm::dvec3 x{2.5, 2.5, 1.0};
  const double a = curve(glm::abs((x - kBox.centerMeters) / kBox.halfExtentsMeters));
  const double b = curve(glm::abs((x - right.centerMeters) / right.halfExtentsMeters));
  const std::map<int, double> w = weightsOf(model.blend(x, kEye));
  EXPECT_NEAR(w.at(0), a / (a + b), 1e-12);
  EXPECT_NEAR(w.at(1), b / (a + b), 1e-12);
  // One box alone gets everything however close to its face; on the face the curve is 0 and
  // the environment shows.
  EXPECT_EQ(weightsOf(model.blend({0.1, 2, 1.5}, kEye)), (std::map<int, double>{{0, 1.0}}));
  EXPECT_EQ(model.blend({0.0, 2, 1.5}, kEye).fallbackWeight, 1.0);
}

// _setup_light takes an object's first max_forward_lights_per_object (8) paired probes: nine
// boxes over a point, the ninth, centred on it, gets nothing, and the first eight share the
// whole weight.
TEST(Godot3Model, APointGetsTheFirstEightBoxesHoldingIt) {
  std::vector<RuntimeProbe> probes;
  for (int i = 0; i < 9; ++i) {
    // Each 0.2 m further along x: the point x = 3.6 lies in all, at the centre of the last.
    const BoxShape box{{2.0 + 0.2 * i, 2.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned};
    probes.push_back(
        probeWithPresets("p" + std::to_string(i), box, box.centerMeters, fadingInside(box)));
  }
  const EngineModel model = godot3Model(exportOf(probes));
  EXPECT_EQ(model.mostProbes, 8u);
  const glm::dvec3 x{3.6, 2.0, 1.5};
  ASSERT_EQ(model.fades(x, kEye).size(), 9u);  // every box holds it
  const std::map<int, double> w = weightsOf(model.blend(x, kEye));
  ASSERT_EQ(w.size(), 8u);
  EXPECT_EQ(w.count(8), 0u);
  double sum = 0.0;
  for (const auto& [probe, weight] : w) sum += weight;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_GT(w.at(7), w.at(0));  // the nearer centre, the larger weight
}

TEST(Godot4Model, BlendDistanceSquaredProductAndTheFarthestProbeFirst) {
  const EngineModel model = godot4Model(oneProbe(kBox));  // blend_distance 1 m
  // At x = 3.5: axis x 1 - (1.5 - 2 + 1) / 1 = 0.5, y and z clamped to 1; product squared.
  const EngineBlend b = model.blend({3.5, 2, 1.5}, kEye);
  EXPECT_NEAR(weightsOf(b)[0], 0.25, 1e-12);
  EXPECT_NEAR(b.fallbackWeight, 0.75, 1e-12);
  // Two boxes, the point 0.5 m inside the right one's -x face (blend 0.25) and deep in the
  // left one (1): seen from the left the right box is farther, visited first and keeps its
  // 0.25; seen from the right the left box comes first and takes all.
  const BoxShape right{{4.5, 2.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned};
  const EngineModel two = godot4Model(
      exportOf({probeWithPresets("left", kBox, kBox.centerMeters, fadingInside(kBox)),
                probeWithPresets("right", right, right.centerMeters, fadingInside(right))}));
  const glm::dvec3 x{3.0, 2.0, 1.5};
  std::map<int, double> w = weightsOf(two.blend(x, {-5.0, 2.0, 1.7}));
  EXPECT_NEAR(w.at(1), 0.25, 1e-12);
  EXPECT_NEAR(w.at(0), 0.75, 1e-12);
  w = weightsOf(two.blend(x, {12.0, 2.0, 1.7}));
  EXPECT_EQ(w, (std::map<int, double>{{0, 1.0}}));
}

// Godot renders each cube face to MAX(max_distance, the capture point's distance to the box's
// face along it) (_render_reflection_probe_step) and drops what lies on or past that plane. With
// max_distance 0, Godot's default, the walls a room's box was fitted to are not in its cubemap:
// the survey leaves that reflection to the fallback. The export's max_distance (the farthest
// corner, 5.591 m from the centre of a 10 x 4 x 3 m room) holds every point of the box.
TEST(GodotModels, EachCubeFaceSeesToMaxDistanceOrTheBoxFaceAndNoFurther) {
  const BoxShape room{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, kUnturned};
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  RuntimeExport exported = oneProbe(room);
  ASSERT_EQ(exported.probes[0].engines.godot->maxDistance, 5.591);
  RuntimeExport godotDefault = exported;
  godotDefault.probes[0].engines.godot->maxDistance = 0.0;
  godotDefault.probes[0].engines.godot4->maxDistance = 0.0;

  const EngineProbe seesTheRoom = godot3Model(exported).probes[0];
  EXPECT_TRUE(capturedAt(seesTheRoom, {10.0, 2.0, 1.5}));   // +x face: 5 m deep
  EXPECT_TRUE(capturedAt(seesTheRoom, {10.0, 4.0, 3.0}));   // the farthest corner
  EXPECT_FALSE(capturedAt(seesTheRoom, {10.6, 2.0, 1.5}));  // 5.6 m: past 5.591
  const EngineProbe faceDeep = godot4Model(godotDefault).probes[0];
  EXPECT_FALSE(capturedAt(faceDeep, {10.0, 2.0, 1.5}));  // on the far plane: dropped
  EXPECT_TRUE(capturedAt(faceDeep, {9.99, 2.0, 1.5}));
  EXPECT_FALSE(capturedAt(faceDeep, {5.0, 2.0, 3.0}));  // the ceiling, 1.5 m up
  EXPECT_TRUE(capturedAt(faceDeep, {9.0, 3.9, 2.9}));   // through the +x face, 4 m deep

  // A wall on the far plane is in or out by the rounding of the traced hit, as in Godot; a box
  // 0.5 m short of the x = 10 wall leaves it out for sure.
  RuntimeExport shortOfTheWall = godotDefault;
  for (auto* g :
       {&shortOfTheWall.probes[0].engines.godot, &shortOfTheWall.probes[0].engines.godot4})
    (*g)->size.x = 9.0;
  ReflectionSample s;
  s.xMeters = {3.0, 1.5, 1.0};
  s.reflected = glm::normalize(glm::dvec3(1.0, 0.3, 0.2));  // meets the x = 10 wall
  s.eyeMeters = s.xMeters + 2.0 * glm::dvec3(-s.reflected.x, -s.reflected.y, s.reflected.z);
  traceTrueHit(level, s);
  for (const Engine e : {Engine::Godot3, Engine::Godot4}) {
    SCOPED_TRACE(std::string(engineName(e)));
    const SurveySampleError seen =
        blendedSampleError(level, engineModel(e, exported, BlendOptions{}), s);
    EXPECT_NEAR(seen.errorDeg, 0.0, 1e-5);
    EXPECT_EQ(seen.uncoveredWeight, 0.0);
    const SurveySampleError clipped =
        blendedSampleError(level, engineModel(e, shortOfTheWall, BlendOptions{}), s);
    EXPECT_TRUE(std::isnan(clipped.errorDeg));
    EXPECT_NEAR(clipped.uncoveredWeight, 1.0, 1e-12);
    EXPECT_EQ(clipped.occludedWeight, 0.0);
  }
}

TEST(BevyModel, FalloffRampsToTheCubesFacesAndTheEnvironmentFillsWhatIsLeft) {
  const BoxShape cube{{2.0, 2.0, 2.0}, {2.0, 2.0, 2.0}, kUnturned};
  const EngineModel model = bevyModel(oneProbe(cube));  // falloff = 1 m / 2 m = 0.5 per axis
  // light_probe_iterator_next: saturate((1 - 2 |p|) / (2 falloff)), p = 1.5 / 4 on x: 0.25.
  const EngineBlend b = model.blend({3.5, 2, 2}, kEye);
  EXPECT_NEAR(weightsOf(b)[0], 0.25, 1e-12);
  EXPECT_NEAR(b.fallbackWeight, 0.75, 1e-12);
  EXPECT_EQ(weightsOf(model.blend({2, 2, 2}, kEye)), (std::map<int, double>{{0, 1.0}}));
}

TEST(BevyModel, LooksUpInTheScaledCubeSoOnlyACubeIsRight) {
  // A cube with the capture point at its centre: the sample direction is the hit's.
  const BoxShape cube{{2.0, 2.0, 2.0}, {2.0, 2.0, 2.0}, kUnturned};
  const EngineProbe exact = bevyModel(oneProbe(cube)).probes[0];
  const glm::dvec3 x{2.5, 1.5, 0.5}, r = glm::normalize(glm::dvec3(1, 2, 3));
  const glm::dvec3 hit = x + (4.0 - x.z) / r.z * r;  // the ceiling z = 4 first
  EXPECT_LT(glm::length(glm::cross(glm::normalize(*engineLookup(exact, x, r)),
                                   glm::normalize(hit - cube.centerMeters))),
            1e-12);
  // A box twice as long in x: the sample direction is (hit - centre) / size per axis.
  const BoxShape box{{4.0, 2.0, 2.0}, {4.0, 2.0, 2.0}, kUnturned};
  const EngineProbe stretched = bevyModel(oneProbe(box)).probes[0];
  const glm::dvec3 hitBox = x + (4.0 - x.z) / r.z * r;
  const glm::dvec3 expected = (hitBox - box.centerMeters) / (2.0 * box.halfExtentsMeters);
  EXPECT_NEAR(glm::distance(*engineLookup(stretched, x, r), expected), 0.0, 1e-12);
}

TEST(EeveeModel, AttenuationAlongEveryAxisFloorIncludedSmallestFirstWorldFills) {
  // Capture at the centre: the influence is the scene's box; falloff = 1 m / 1.5 m, so fac =
  // saturate(1.5 - 1.5 |local|) per axis.
  const EngineModel model = eeveeModel(oneProbe(kBox));
  EXPECT_EQ(weightsOf(model.blend(kBox.centerMeters, kEye)), (std::map<int, double>{{0, 1.0}}));
  const EngineBlend side = model.blend({3.5, 2.0, 1.5}, kEye);  // local x 0.75
  EXPECT_NEAR(weightsOf(side)[0], 1.5 - 1.5 * 0.75, 1e-12);
  EXPECT_NEAR(side.fallbackWeight, 1.0 - (1.5 - 1.5 * 0.75), 1e-12);
  // On the floor (local z = -1) the probe gives nothing: the world probe shows.
  EXPECT_EQ(model.blend({2.0, 2.0, 0.0}, kEye).fallbackWeight, 1.0);
  // A capture point off centre: the influence grows to cover the scene's volume from it.
  const EngineModel off =
      eeveeModel(exportOf({probeWithPresets("a", kBox, {1.0, 2.0, 1.5}, fadingInside(kBox))}));
  const BoxShape& parallax = std::get<BoxShape>(off.probes[0].projection);
  EXPECT_EQ(parallax.centerMeters, glm::dvec3(1.0, 2.0, 1.5));
  EXPECT_GT(off.blend({3.9, 2.0, 1.5}, kEye).weights.size(), 0u);
}

// A 10 x 4 x 3 m room whose probe's box is the room, captured at its centre: every engine that
// projects on the room itself looks up the true hit, so the blended error is 0 wherever a probe
// weighs; Bevy looks up in a stretched cube, so it is off. The mirror is 1 m over the floor,
// inside every engine's fade.
TEST(EngineModels, AnExactBoxRoomIsExactWhereTheEngineProjectsOnTheRoom) {
  const BoxShape room{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, kUnturned};
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  const RuntimeExport presets = oneProbe(room);
  ReflectionSample s;
  s.xMeters = {3.0, 1.5, 1.0};
  s.reflected = glm::normalize(glm::dvec3(1.0, 0.3, 0.2));  // meets the x = 10 wall
  s.eyeMeters = s.xMeters + 2.0 * glm::dvec3(-s.reflected.x, -s.reflected.y, s.reflected.z);
  traceTrueHit(level, s);
  const glm::dvec3 c = room.centerMeters;
  const glm::dvec3 toHit = s.trueHitMeters - c;
  ASSERT_NEAR(s.trueHitMeters.x, 10.0, 1e-6);
  // Bevy: the hit over the box's full size per axis.
  const double bevy = angleBetweenDeg(toHit / (2.0 * room.halfExtentsMeters), toHit);
  EXPECT_GT(bevy, 10.0);
  for (const Engine e : kEngines) {
    SCOPED_TRACE(std::string(engineName(e)));
    const SurveySampleError err =
        blendedSampleError(level, engineModel(e, presets, BlendOptions{}), s);
    const double expected = e == Engine::Bevy ? bevy : 0.0;
    EXPECT_NEAR(err.errorDeg, expected, 1e-5);
  }
}

// The same room's floor lies on the probe box's bottom face. Engines that fade inside the box
// (HDRP, Godot 3's curve, Godot 4's blend distance, Bevy's falloff, EEVEE's attenuation) give
// it no probe at all: the sky shows. Unreal's transition leaves 0.198 on the face; Unity fades
// outside its box, whose bottom the export keeps at the floor; the generic model takes its
// weights 5 cm over the floor.
TEST(EngineModels, AFloorOnTheBoxFaceIsLeftToTheSkyByEnginesThatFadeInside) {
  const BoxShape room{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, kUnturned};
  const RuntimeExport presets = oneProbe(room);
  const glm::dvec3 floor{3.0, 1.5, 0.0};
  const std::map<Engine, double> sky = {
      {Engine::Generic, 0.0},   {Engine::Unity, 0.0},
      {Engine::UnityHdrp, 1.0}, {Engine::Unreal, 1.0 - (1.0 - smoothstep(0.0, 0.7, 0.5))},
      {Engine::Godot3, 1.0},    {Engine::Godot4, 1.0},
      {Engine::Bevy, 1.0},      {Engine::Eevee, 1.0}};
  for (const Engine e : kEngines) {
    SCOPED_TRACE(std::string(engineName(e)));
    EXPECT_NEAR(engineModel(e, presets, BlendOptions{}).blend(floor, kEye).fallbackWeight,
                sky.at(e), 1e-12);
  }
}

// One probe in a 6 x 4 x 3 m room whose kept proxy is the room's box, its influence the room's
// right two thirds (x in [-1, 3]) fading 0.5 m inside each face.
struct OneRoomProbe {
  Scene scene;
  std::vector<ProbeProxyBuild> builds;
};

OneRoomProbe oneRoomProbe() {
  OneRoomProbe r;
  r.scene.file = "room.scene.json";
  Probe probe;
  probe.name = "a";
  probe.captureMeters = {1.0, 0.0, 1.6};
  probe.influence = BoxInfluence{{1.0, 0.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned, {1.5, 1.5, 1.0}};
  r.scene.probes.push_back(probe);
  ProbeProxyBuild build;
  build.probe = "a";
  ProxyCandidate room;
  room.origin = CandidateOrigin::Aabb;
  room.shape = BoxShape{{0.0, 0.0, 1.5}, {3.0, 2.0, 1.5}, kUnturned};
  room.error.p95Deg = 0.0;
  build.candidates.push_back(room);
  r.builds.push_back(build);
  return r;
}

TEST(EnginePresetPolicy, TheDefaultIsTheBuildExportByteForByte) {
  const OneRoomProbe r = oneRoomProbe();
  EXPECT_EQ(runtimeExportJson(makeRuntimeExport(r.scene, r.builds, EnginePresetPolicy{})),
            runtimeExportJson(makeRuntimeExport(r.scene, r.builds)));
}

TEST(EnginePresetPolicy, ClearingTheFloorLowersTheBoxesBottomByTheFadeAndNothingElse) {
  const OneRoomProbe r = oneRoomProbe();
  EnginePresetPolicy clear;
  clear.clearTheFloor = true;
  const RuntimeEngines e = makeRuntimeExport(r.scene, r.builds, clear).probes[0].engines;
  const BoxShape box = unrealPresetBox(*e.unrealBox).box;
  EXPECT_NEAR(box.centerMeters.z - box.halfExtentsMeters.z, -0.5, 1e-12);  // floor 0, fade 0.5
  EXPECT_NEAR(box.centerMeters.z + box.halfExtentsMeters.z, 3.0, 1e-12);
  EXPECT_NEAR(box.halfExtentsMeters.x, 3.0, 1e-12);
  // HDRP's influence goes down with it, its fade kept: the floor is a full fade inside it.
  const HdrpHeld hdrp = unityHdrpHeld(*e.unityHdrp);
  EXPECT_NEAR(hdrp.influenceBox.centerMeters.z - hdrp.influenceBox.halfExtentsMeters.z, -0.5,
              1e-12);
  EXPECT_NEAR(hdrp.blendNegative.z, 0.5, 1e-12);
  // The Godot 4 model now gives the floor under the capture point the probe's full weight;
  // the export as `build` writes it only lowers the bottom 2 cm, 0.04 of Godot 4's 0.5 m blend:
  // (0.02 / 0.5)^2 of the weight.
  const RuntimeExport plain = makeRuntimeExport(r.scene, r.builds);
  const RuntimeExport cleared = makeRuntimeExport(r.scene, r.builds, clear);
  const glm::dvec3 floor{1.0, 0.0, 0.0};
  EXPECT_NEAR(godot4Model(plain).blend(floor, kEye).fallbackWeight, 1.0 - 0.04 * 0.04, 1e-12);
  EXPECT_EQ(godot4Model(cleared).blend(floor, kEye).fallbackWeight, 0.0);
}

TEST(EnginePresetPolicy, ClippingCutsTheBoxInPlanToTheInfluenceAndScalingWidensTheFade) {
  const OneRoomProbe r = oneRoomProbe();
  EnginePresetPolicy clip;
  clip.clipToInfluence = true;
  clip.fadeScale = 2.0;
  const RuntimeEngines e = makeRuntimeExport(r.scene, r.builds, clip).probes[0].engines;
  const BoxShape box = godotPresetBox(*e.godot).box;
  EXPECT_NEAR(box.centerMeters.x - box.halfExtentsMeters.x, -1.0, 1e-9);  // the influence's
  EXPECT_NEAR(box.centerMeters.x + box.halfExtentsMeters.x, 3.0, 1e-9);   // room's and its
  EXPECT_NEAR(box.halfExtentsMeters.y, 2.0, 1e-9);
  EXPECT_NEAR(box.halfExtentsMeters.z, 1.51, 1e-9);  // the height stays, the floor 2 cm inside
  EXPECT_NEAR(e.godot->blendDistance, 1.0, 1e-12);   // twice the 0.5 m fade
  EXPECT_EQ(makeRuntimeExport(r.scene, r.builds, EnginePresetPolicy{0.0})
                .probes[0]
                .engines.godot->blendDistance,
            0.0);
  EXPECT_THROW(makeRuntimeExport(r.scene, r.builds, EnginePresetPolicy{5.0}),
               std::invalid_argument);
}

TEST(EnginePresetPolicy, EeveeAtTheBoxCentreProjectsOnTheBoxWithFullWeightOverItAndFadesBeyond) {
  const OneRoomProbe r = oneRoomProbe();
  EnginePresetPolicy centred;
  centred.eeveeAtBoxCentre = true;
  const EngineModel model = eeveeModel(makeRuntimeExport(r.scene, r.builds, centred));
  // The room's box, its bottom 2 cm under the floor: centre z 1.49, half-height 1.51.
  const BoxShape& parallax = std::get<BoxShape>(model.probes[0].projection);
  EXPECT_NEAR(glm::distance(parallax.centerMeters, glm::dvec3(0.0, 0.0, 1.49)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(parallax.halfExtentsMeters, glm::dvec3(3.0, 2.0, 1.51)), 0.0, 1e-12);
  EXPECT_EQ(model.probes[0].captureMeters, parallax.centerMeters);
  // Full weight up to the room's walls, its floor's corner included.
  EXPECT_EQ(model.blend({2.99, 1.99, 0.0}, kEye).fallbackWeight, 0.0);
  // Beyond, the influence (the box grown by the 0.5 m fade over its 1.51 m shortest side)
  // fades: half way through the fade above the ceiling, half the weight.
  EXPECT_NEAR(model.blend({0.0, 0.0, 3.0 + 0.25}, kEye).fallbackWeight, 0.5, 1e-9);
  EXPECT_NEAR(model.blend({0.0, 0.0, 3.0 + 0.5}, kEye).fallbackWeight, 1.0, 1e-9);
}

TEST(EngineModels, TheGenericModelIsTheSurveysOwnBlend) {
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  BoxInfluence left, right;
  left.centerMeters = {3.0, 2.0, 1.5};
  right.centerMeters = {7.0, 2.0, 1.5};
  left.halfExtentsMeters = right.halfExtentsMeters = {3.0, 2.0, 1.5};
  left.innerHalfExtentsMeters = right.innerHalfExtentsMeters = {1.0, 2.0, 1.5};
  const std::vector<SurveyProbe> probes = {
      {{3.0, 2.0, 1.5}, left, BoxShape{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, kUnturned}},
      {{7.0, 2.0, 1.5}, right, InfiniteShape{}}};
  const std::vector<InfluenceVolume> volumes = {left, right};
  const std::vector<glm::dvec3> captures = {probes[0].captureMeters, probes[1].captureMeters};
  const std::vector<ProxyShape> shapes = {probes[0].proxy, probes[1].proxy};
  const EngineModel model = genericModel(captures, volumes, shapes, BlendOptions{});
  for (double x = 0.5; x < 10.0; x += 0.75) {
    ReflectionSample s;
    s.xMeters = {x, 2.0, 0.0};
    s.reflected = glm::normalize(glm::dvec3(1.0, 0.2, 1.0));
    s.eyeMeters = s.xMeters + glm::dvec3(-s.reflected.x, -s.reflected.y, s.reflected.z);
    traceTrueHit(level, s);
    const SurveySampleError a = blendedSampleError(level, probes, volumes, s, BlendOptions{});
    const SurveySampleError b = blendedSampleError(level, model, s);
    EXPECT_EQ(a.errorDeg, b.errorDeg) << "x = " << x;
    EXPECT_EQ(a.uncoveredWeight, b.uncoveredWeight);
  }
}

}  // namespace
}  // namespace probeproxy
