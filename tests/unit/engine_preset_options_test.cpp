// Which of each probe's boxes an engine gets (geometry/layout/engine_preset_options.h): in a
// box room whose exact box is known, a box that cuts the room short is left out or traded for
// the room's own, and the floor surveyed under the engine gets better by what the search saw.

#include "geometry/layout/engine_preset_options.h"
#include "geometry/builtin/box_room.h"
#include "geometry/builtin/l_room.h"
#include "geometry/engines/engine_model.h"
#include "geometry/layout/engine_presets.h"
#include "geometry/survey/run_survey.h"
#include "tests/unit/engine_test_probes.h"

#include <gtest/gtest.h>

#include <string>

namespace probeproxy {
namespace {

constexpr glm::dquat kUnturned{1, 0, 0, 0};
const BoxShape kRoom{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, kUnturned};      // [0, 10] x [0, 4] x [0, 3]
const BoxShape kEastHalf{{8.0, 2.0, 1.5}, {2.0, 2.0, 1.5}, kUnturned};  // cuts the room at x 6

// A probe whose influence is its box with a 1 cm fade, so that Unity's fade outside the box
// leaves no floor to the sky.
RuntimeProbe unityProbe(const std::string& name, const BoxShape& box, glm::dvec3 capture) {
  return boxProbe(name, box, capture, 0.01);
}

struct Room {
  LevelRayCaster level{boxRoom({0, 0, 0}, {10, 4, 3})};
  SurveyOptions options;
  SurveyFloor floor;
  Room() {
    options.engine = Engine::Unity;
    options.samplesPerCell = 2;
    const std::vector<glm::dvec3> seeds = {{5.0, 2.0, 1.5}};
    floor = prepareSurveyFloor(seeds, level, options);
  }
  double badShare(const RuntimeExport& presets) const {
    const SurveyFigures f = surveyModel(unityModel(presets), floor, level, options).figures;
    return f.overToleranceShare + f.uncoveredShare;
  }
};

const glm::dvec3 kWest{2.5, 2.0, 1.5}, kEast{8.0, 2.0, 1.5};

// The floor an engine does not get right: over the tolerance, left to its fallback, or shown by
// probes that cannot see what it reflects (what the option search minimises).
double notRight(const SurveyFigures& f) {
  return f.overToleranceShare + f.uncoveredShare + f.occludedShare;
}

TEST(EnginePresetOptions, AProbeWhoseSmallerBoxCutsTheRoomShortIsLeftOut) {
  const Room room;
  // Unity puts the smaller box on top: the east half reflects a wall at x 6 that is not there.
  const RuntimeExport both =
      exportOf({unityProbe("west", kRoom, kWest), unityProbe("east", kEastHalf, kEast)});
  const std::vector<int> probeOf = {0, 1};
  const std::vector<int> chosen =
      chooseEngineOptions(unityModel(both), probeOf, {0, 1}, room.floor, room.level, 5.0);
  EXPECT_EQ(chosen, (std::vector<int>{0, -1}));
  // An artist's probes kept by the layout stay in every engine, however they render.
  EXPECT_EQ(chooseEngineOptions(unityModel(both), probeOf, {0, 1}, room.floor, room.level, 5.0,
                                /*keptProbes=*/2),
            (std::vector<int>{0, 1}));
  const double before = room.badShare(both);
  const double after = room.badShare(exportOf({unityProbe("west", kRoom, kWest)}));
  // Rays from the east half that meet the cut before the ceiling: a few percent of the floor.
  EXPECT_GT(before, 0.03);
  EXPECT_LT(after, 0.1 * before);  // the room's exact box from anywhere in it
}

TEST(EnginePresetOptions, AProbeTakesTheBoxOfTheRoomOverOneThatCutsItShort) {
  const Room room;
  // One probe, two of its boxes: the cut one it starts with, and the room's.
  const RuntimeExport options =
      exportOf({unityProbe("east/cut", kEastHalf, kEast), unityProbe("east/room", kRoom, kEast)});
  const std::vector<int> probeOf = {0, 0};
  EXPECT_EQ(chooseEngineOptions(unityModel(options), probeOf, {0}, room.floor, room.level, 5.0),
            (std::vector<int>{1}));
  // Left out, the whole floor would show the sky: the search does not leave it.
  EXPECT_EQ(chooseEngineOptions(unityModel(exportOf({unityProbe("east/room", kRoom, kEast)})),
                                std::vector<int>{0}, {0}, room.floor, room.level, 5.0),
            (std::vector<int>{0}));
}

// Unity's importance, as `layout --engine unity` offers it: each probe at 1 (Unity's default)
// and at 2.
RuntimeProbe atImportance(RuntimeProbe probe, int importance) {
  probe.name.append("/").append(std::to_string(importance));
  probe.engines.unity->importance = importance;
  return probe;
}

TEST(EnginePresetOptions, TheRoomsProbeIsRaisedOverASmallerBoxThatCutsItShort) {
  const Room room;
  // The west probe's box stops 0.25 m short of the east wall; the east probe's smaller box, on
  // top by default, cuts the room at x 6. Leaving the east probe out leaves the last 0.25 m to
  // the sky; raising the west probe over it keeps the east probe there and the rest right.
  const BoxShape west{{4.875, 2.0, 1.5}, {4.875, 2.0, 1.5}, kUnturned};  // [0, 9.75] x [0, 4]
  const RuntimeProbe w = unityProbe("west", west, kWest);
  const RuntimeProbe e = unityProbe("east", kEastHalf, kEast);
  const RuntimeExport options =
      exportOf({atImportance(w, 1), atImportance(w, 2), atImportance(e, 1), atImportance(e, 2)});
  const std::vector<int> probeOf = {0, 0, 1, 1};
  EXPECT_EQ(chooseEngineOptions(unityModel(options), probeOf, {0, 2}, room.floor, room.level, 5.0),
            (std::vector<int>{1, 2}));
  const double before = room.badShare(exportOf({atImportance(w, 1), atImportance(e, 1)}));
  const double raised = room.badShare(exportOf({atImportance(w, 2), atImportance(e, 1)}));
  const double leftOut = room.badShare(exportOf({atImportance(w, 1)}));
  EXPECT_LT(raised, 0.5 * before);
  EXPECT_LT(raised, leftOut);
}

TEST(EnginePresetOptions, AProbeIsNotLeftOutForOneThatCannotSeeWhatItsFloorReflects) {
  // An L of two arms round a corner room: the y arm's probe has the arm's own box, on top of the
  // x arm's probe whose box is the L's bounds. Without it the x arm's probe, round the corner,
  // would show the y arm's floor what stands between: hidden, not right, however small the
  // y arm's own errors where its box cuts the corner short.
  const LevelRayCaster level{lRoom({4.0, 6.0, 3.0})};
  SurveyOptions options;
  options.engine = Engine::Unity;
  options.samplesPerCell = 2;
  const std::vector<glm::dvec3> seeds = {{2.0, 2.0, 1.5}};
  const SurveyFloor floor = prepareSurveyFloor(seeds, level, options);
  const BoxShape bounds{{5.0, 5.0, 1.5}, {5.0, 5.0, 1.5}, kUnturned};
  const BoxShape yArm{{2.0, 7.0, 1.5}, {2.0, 3.0, 1.5}, kUnturned};
  const RuntimeExport both =
      exportOf({unityProbe("x", bounds, {8.0, 2.0, 1.5}), unityProbe("y", yArm, {2.0, 8.0, 1.5})});
  EXPECT_EQ(
      chooseEngineOptions(unityModel(both), std::vector<int>{0, 1}, {0, 1}, floor, level, 5.0),
      (std::vector<int>{0, 1}));
  // What leaving it out would do: most of the y arm shown by a probe that cannot see it.
  const SurveyFigures alone =
      surveyModel(unityModel(exportOf({unityProbe("x", bounds, {8.0, 2.0, 1.5})})), floor, level,
                  options)
          .figures;
  const SurveyFigures kept = surveyModel(unityModel(both), floor, level, options).figures;
  EXPECT_GT(alone.occludedShare, kept.occludedShare + 0.1);
  EXPECT_LT(alone.overToleranceShare + alone.uncoveredShare,
            kept.overToleranceShare + kept.uncoveredShare);
}

// Godot 3 gives an object its first 8 paired probes; which 8 where more boxes hold a point
// depends on how the level's meshes are cut. Ten probes along the room, each starting with the
// room's box (ten over every point) and offered its own tenth: the search keeps at most 8 boxes
// over any sample (eight room boxes: the other two left out), and its floor is as right as
// with one room box.
TEST(EnginePresetOptions, Godot3KeepsAtMostEightBoxesOverAPoint) {
  Room room;
  room.options.engine = Engine::Godot3;
  std::vector<RuntimeProbe> options;
  std::vector<int> probeOf, start;
  // Boxes reach 0.5 m under the floor, as the export lowers them: Godot 3's weight is 0 on a
  // box's faces.
  const BoxShape roomBox{{5.0, 2.0, 1.25}, {5.0, 2.0, 1.75}, kUnturned};
  for (int i = 0; i < 10; ++i) {
    const glm::dvec3 capture{0.5 + i, 2.0, 1.5};
    const BoxShape tenth{{0.5 + i, 2.0, 1.25}, {0.5, 2.0, 1.75}, kUnturned};
    start.push_back(static_cast<int>(options.size()));
    options.push_back(boxProbe("p" + std::to_string(i) + "/room", roomBox, capture, 0.0));
    options.push_back(boxProbe("p" + std::to_string(i) + "/own", tenth, capture, 0.0));
    probeOf.insert(probeOf.end(), {i, i});
  }
  const std::vector<int> chosen = chooseEngineOptions(godot3Model(exportOf(options)), probeOf,
                                                      start, room.floor, room.level, 5.0);
  std::vector<RuntimeProbe> kept;
  for (const int c : chosen)
    if (c >= 0) kept.push_back(options[static_cast<std::size_t>(c)]);
  const RuntimeExport written = exportOf(kept);
  const EngineModel after = godot3Model(written);
  std::size_t most = 0;
  for (const FloorSample& f : room.floor.samples)
    most = std::max(most, after.fades(f.sample.xMeters, f.sample.eyeMeters).size());
  EXPECT_EQ(most, 8u);
  const auto bad = [&](const EngineModel& m) {
    return notRight(surveyModel(m, room.floor, room.level, room.options).figures);
  };
  EXPECT_LE(
      bad(after),
      bad(godot3Model(exportOf(std::vector<RuntimeProbe>(options.begin(), options.begin() + 1)))) +
          0.01);
}

TEST(EnginePresetOptions, TheGenericModelKeepsWhatItStartsWith) {
  const Room room;
  const std::vector<glm::dvec3> captures = {kWest, kEast};
  const std::vector<InfluenceVolume> influences = {unityProbe("west", kRoom, kWest).influence,
                                                   unityProbe("east", kEastHalf, kEast).influence};
  const std::vector<ProxyShape> shapes = {kRoom, kEastHalf};
  const EngineModel generic = genericModel(captures, influences, shapes, BlendOptions{});
  EXPECT_EQ(
      chooseEngineOptions(generic, std::vector<int>{0, 1}, {0, 1}, room.floor, room.level, 5.0),
      (std::vector<int>{0, 1}));
  EXPECT_THROW(chooseEngineOptions(generic, std::vector<int>{0}, {0}, room.floor, room.level, 5.0),
               std::invalid_argument);
}

// EEVEE centres both volumes on the capture point, so a probe captured off its room's centre
// gets a parallax box about that point, not the room. A layout for EEVEE captures it at its
// box's centre instead, where the parallax box is the room and every reflection is right.
TEST(EnginePresets, EeveeCapturesAnOffCentreProbeAtItsBoxCentreWhereItHoldsTheRoom) {
  const Room room;
  SurveyOptions options = room.options;
  options.engine = Engine::Eevee;
  Scene scene;
  scene.file = "room.scene.json";
  Probe probe;
  probe.name = "p";
  probe.captureMeters = {2.0, 1.0, 1.6};
  probe.influence = BoxInfluence{kRoom.centerMeters, kRoom.halfExtentsMeters, kUnturned,
                                 kRoom.halfExtentsMeters - 0.5};
  scene.probes.push_back(probe);
  ProbeProxyBuild build;
  build.probe = "p";
  ProxyCandidate box;
  box.origin = CandidateOrigin::Aabb;
  box.shape = kRoom;
  build.candidates.push_back(box);
  const std::vector<ProbeProxyBuild> builds = {build};
  const Engine eevee = Engine::Eevee;
  const std::vector<EnginePresetChoice> choices =
      choosePresetsForEngines(std::span(&eevee, 1), scene, builds, room.level, room.floor,
                              room.floor, options, ProbeEntries{});
  ASSERT_EQ(choices.size(), 1u);
  const EnginePresetChoice& c = choices[0];
  EXPECT_EQ(c.atBoxCentre, std::vector<bool>{true});
  EXPECT_EQ(c.boxFrom, std::vector<int>{kDefaultBox});
  // Captured where the scene says, under every policy, most of the floor was not right: off,
  // or left to the world probe by influences fading over it.
  for (const EnginePresetTrial& t : c.trials) EXPECT_GT(notRight(t.figures), 0.5);
  EXPECT_LT(notRight(c.survey.figures), 0.01);
  // What is written is what was measured: the entry at the box's centre, the room as its
  // parallax volume, its bottom under the floor as the policy lowered it.
  const RuntimeExport written = exportForEngines(scene, builds, choices);
  const EngineModel model = eeveeModel(written);
  ASSERT_EQ(model.probes.size(), 1u);
  const BoxShape& parallax = std::get<BoxShape>(model.probes[0].projection);
  EXPECT_EQ(model.probes[0].captureMeters, parallax.centerMeters);
  EXPECT_NEAR(parallax.centerMeters.x, 5.0, 1e-12);
  EXPECT_NEAR(parallax.centerMeters.y, 2.0, 1e-12);
  EXPECT_NEAR(parallax.halfExtentsMeters.x, 5.0, 1e-12);
  EXPECT_NEAR(parallax.halfExtentsMeters.y, 2.0, 1e-12);
  EXPECT_NEAR(parallax.centerMeters.z + parallax.halfExtentsMeters.z, 3.0, 1e-12);
  EXPECT_LE(parallax.centerMeters.z - parallax.halfExtentsMeters.z, -0.02 + 1e-12);
  EXPECT_EQ(surveyModel(model, room.floor, room.level, options).figures.overToleranceShare,
            c.survey.figures.overToleranceShare);
}

// A policy is judged with the probes' entries chosen under it, not before. The west probe's box
// is the room, its influence the west 6 m; the east probe stands behind the east wall (it sees
// none of the room) with a box over the east 7 m and an influence over the east 4 m. Before the
// entries, cutting the boxes to the influences wins: the east box, on top (Unreal draws the
// smaller box over the larger), then shows less floor it cannot see. With the east probe left
// out, which both policies do, the uncut room box is right everywhere and the cut one leaves the
// east of the room to the sky.
TEST(EnginePresets, APolicyIsKeptByTheFloorItsEntriesFinishNotByItsTrialBefore) {
  const Room room;
  Scene scene;
  scene.file = "room.scene.json";
  const auto probe = [](const std::string& name, glm::dvec3 capture, double fromX, double toX) {
    Probe p;
    p.name = name;
    p.captureMeters = capture;
    const glm::dvec3 centre{0.5 * (fromX + toX), 2.0, 1.5}, half{0.5 * (toX - fromX), 2.0, 1.5};
    p.influence = BoxInfluence{centre, half, kUnturned, half - 0.01};
    return p;
  };
  scene.probes = {probe("west", kWest, 0.0, 6.0), probe("east", {12.0, 2.0, 1.5}, 6.0, 10.0)};
  const auto build = [](const std::string& name, const BoxShape& box) {
    ProbeProxyBuild b;
    b.probe = name;
    ProxyCandidate c;
    c.origin = CandidateOrigin::Aabb;
    c.shape = box;
    b.candidates.push_back(c);
    return b;
  };
  const BoxShape eastSeven{{6.5, 2.0, 1.5}, {3.5, 2.0, 1.5}, kUnturned};  // [3, 10]
  const std::vector<ProbeProxyBuild> builds = {build("west", kRoom), build("east", eastSeven)};
  const Engine unreal = Engine::Unreal;
  const std::vector<EnginePresetChoice> choices =
      choosePresetsForEngines(std::span(&unreal, 1), scene, builds, room.level, room.floor,
                              room.floor, room.options, ProbeEntries{});
  ASSERT_EQ(choices.size(), 1u);
  const EnginePresetChoice& c = choices[0];
  // Before the entries the best cut policy beat every uncut one; both kinds were finished.
  double bestCut = 1.0, bestUncut = 1.0;
  const EnginePresetTrial* cutFinished = nullptr;
  for (const EnginePresetTrial& t : c.trials) {
    double& best = t.policy.clipToInfluence ? bestCut : bestUncut;
    best = std::min(best, notRight(t.figures));
    if (t.finished && t.policy.clipToInfluence) cutFinished = &t;
  }
  EXPECT_LT(bestCut + 0.05, bestUncut);
  ASSERT_NE(cutFinished, nullptr);
  // Finished, the uncut boxes won, the east probe left out, and the floor is right but what the
  // room box's corners and fades miss; the cut policy left the east 4 m (40%) to the sky.
  EXPECT_FALSE(c.policy.clipToInfluence);
  EXPECT_EQ(c.boxFrom, (std::vector<int>{kDefaultBox, kLeftOut}));
  EXPECT_LT(notRight(c.survey.figures), 0.05);
  EXPECT_GT(notRight(*cutFinished->finished), 0.35);
}

}  // namespace
}  // namespace probeproxy
