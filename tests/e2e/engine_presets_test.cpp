// Each engine preset, read from proxies.json as plain JSON (not through probeproxy's
// reader or its frame code), turned back into a box in world metres with that engine's own
// formula, as the engine's shader or node code applies it (docs/engines.md cites each one), is
// the box the export says it came from: corners within 1e-6 m, and the capture point and the
// fade distance too where the engine has them. On every suite level and two corpus maps.
// Each test prints its worst error ("worst ... m"): docs/engines.md quotes them.

#include "core/proxy/proxy_candidate.h"
#include "geometry/export/kept_box.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/load_level.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/scene/scene_file.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

namespace probeproxy {
namespace {

constexpr double kToleranceMeters = 1e-6;

struct Level {
  std::string name;
  std::filesystem::path scene;
};

std::vector<Level> levels() {
  const std::filesystem::path suite = PROBEPROXY_SUITE_DIR;
  const std::filesystem::path corpus = PROBEPROXY_CORPUS_SCENES;
  std::vector<Level> out;
  for (const char* level : {"corridor", "l_room", "u_corridors", "hall_pillars", "attic",
                            "round_room", "courtyard", "tiny_closet", "hangar"}) {
    out.push_back({level, suite / level / (std::string(level) + ".scene.json")});
  }
  // The two smallest corpus maps (tests/corpus/CMakeLists.txt builds the same two).
  for (const char* map : {"eggandbacon", "downer"}) {
    out.push_back({map, corpus / map / (std::string(map) + ".scene.json")});
  }
  return out;
}

// The level built and exported once per test; `json` is proxies.json as written.
struct Exported {
  Scene scene;
  std::vector<ProbeProxyBuild> builds;
  nlohmann::json json;
};

Exported exportLevel(const Level& level, const std::string& engine) {
  Exported e;
  e.scene = readSceneFile(level.scene);
  const LevelRayCaster caster(loadLevel(e.scene));
  e.builds = buildSceneProxies(e.scene, caster, ProxyBuildOptions{});
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "probeproxy-engine-presets" / engine / level.name;
  std::filesystem::remove_all(out);
  writeRuntimeExport(e.scene, e.builds, out);
  std::ifstream in(out / "proxies.json");
  e.json = nlohmann::json::parse(in);
  std::filesystem::remove_all(out);
  return e;
}

glm::dvec3 vec3(const nlohmann::json& v) {
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

// [x, y, z, w], as every engine entry writes it.
glm::dquat quatXyzw(const nlohmann::json& v) {
  glm::dquat q;
  q.x = v[0].get<double>();
  q.y = v[1].get<double>();
  q.z = v[2].get<double>();
  q.w = v[3].get<double>();
  return q;
}

// Corners in the order of the signs (x fastest), so that two boxes compare corner by corner:
// a box with the same corners in another order is not the same box.
std::vector<glm::dvec3> corners(glm::dvec3 center, const glm::dquat& rotation,
                                glm::dvec3 halfExtents) {
  std::vector<glm::dvec3> out;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 s((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    out.push_back(center + rotation * (s * halfExtents));
  }
  return out;
}

// The largest distance from a corner of one set to the nearest corner of the other (the sets'
// Hausdorff distance): the engines' boxes may name their axes in another order.
double cornerDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  double worst = 0.0;
  for (const auto* from : {&a, &b}) {
    const auto& to = from == &a ? b : a;
    for (const glm::dvec3& p : *from) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const glm::dvec3& q : to) nearest = std::min(nearest, glm::distance(p, q));
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}

// The box the entry says it was made from: the build's candidate of that name, as a box, its
// bottom kFloorClearanceMeters under the floor as every engine's box (runtime_export.h).
BoxShape sourceBox(const ProbeProxyBuild& build, const nlohmann::json& entry) {
  const std::string name = entry["candidate"].get<std::string>();
  for (std::size_t c = 0; c < build.candidates.size(); ++c) {
    if (candidateName(build.candidates[c]) != name) continue;
    EXPECT_EQ(entry["kept_proxy"].get<bool>(), c == build.kept) << build.probe << " " << name;
    const std::optional<BoxShape> box = keptBox(build.candidates[c].shape);
    if (box) return withBottomLowered(*box, kFloorClearanceMeters);
  }
  ADD_FAILURE() << build.probe << ": no box candidate named " << name;
  return {};
}

std::vector<glm::dvec3> worldCorners(const BoxShape& box) {
  return corners(box.centerMeters, box.worldFromBox, box.halfExtentsMeters);
}

// The influence's fade, written out from docs/engines.md's rule (not transitionDistanceMeters):
// the smallest outer - inner over the axes that fade at all, else 0.
double influenceFadeMeters(const InfluenceVolume& influence) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    double fade = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double f = box->halfExtentsMeters[a] - box->innerHalfExtentsMeters[a];
      if (f > 0.0 && (fade == 0.0 || f < fade)) fade = f;
    }
    return fade;
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return std::max(0.0, sphere.radiusMeters - sphere.innerRadiusMeters);
}

// Worst figures over a level, printed at the end of each test.
struct Worst {
  double corners = 0.0, capture = 0.0, fade = 0.0;
  int entries = 0;
  void print(const std::string& engine, const std::string& level) const {
    std::printf("%s %s: %d entries, worst corner %.3g m, capture %.3g m, fade %.3g m\n",
                engine.c_str(), level.c_str(), entries, corners, capture, fade);
    ::testing::Test::RecordProperty("entries", entries);
    ::testing::Test::RecordProperty("worst_corner_m", std::to_string(corners));
  }
};

class EnginePreset : public ::testing::TestWithParam<Level> {};

// Unity: left-handed, Y up, metres; Unity (u, v, w) is world (-u, -w, v). The box projected
// on is [position + center -+ (size / 2 + blend_distance)]: the measured box with its bottom
// blend_distance lower; axis-aligned in Unity's world
// (UnityStandardUtils.cginc, BoxProjectedCubemapDirection: boxMin / boxMax in world space;
// Internal-DeferredReflections.shader grows them by the blend distance); the lookup is made from
// `position` (cubemapCenter), which must be the capture point.
TEST_P(EnginePreset, UnityBoxIsPositionPlusCenterWithFullSizeGrownByTheBlendDistance) {
  const Exported e = exportLevel(GetParam(), "unity");
  const auto world = [](glm::dvec3 u) { return glm::dvec3(-u.x, -u.z, u.y); };
  Worst worst;
  for (std::size_t i = 0; i < e.builds.size(); ++i) {
    const nlohmann::json& entry = e.json["probes"][i]["engines"]["unity_reflection_probe"];
    if (entry.is_null()) continue;
    ++worst.entries;
    const glm::dvec3 position = vec3(entry["position"]);
    const glm::dvec3 center = vec3(entry["center"]);
    const glm::dvec3 half = vec3(entry["size"]) / 2.0 + entry["blend_distance"].get<double>();
    std::vector<glm::dvec3> unity;
    for (const glm::dvec3& c : corners(position + center, glm::dquat(1, 0, 0, 0), half))
      unity.push_back(world(c));
    // The measured box, but its bottom blend_distance lower (Unity's size keeps the floor).
    BoxShape box = sourceBox(e.builds[i], entry);
    const double below = entry["blend_distance"].get<double>();
    box.centerMeters.z -= 0.5 * below;
    box.halfExtentsMeters.z += 0.5 * below;
    EXPECT_LT(std::abs(std::abs(box.worldFromBox.w) - 1.0), 1e-12) << "Unity got a turned box";
    worst.corners = std::max(worst.corners, cornerDistance(unity, worldCorners(box)));
    worst.capture =
        std::max(worst.capture, glm::distance(world(position), e.scene.probes[i].captureMeters));
    EXPECT_TRUE(entry["box_projection"].get<bool>());
  }
  EXPECT_LE(worst.corners, kToleranceMeters);
  EXPECT_LE(worst.capture, kToleranceMeters);
  worst.print("unity", GetParam().name);
}

// Unreal: left-handed, Z up, centimetres; Unreal (x, y, z) is world (x, -y, z) / 100. The box
// is the unit box [-1, 1]^3 under location, rotation and Scale 3D (= half-extents, cm)
// (ReflectionEnvironmentShared.ush GetLookupVectorForBoxCapture: "an AABB with mins at -1 and
// maxs at 1"); the cubemap's centre is location + CaptureOffset, in world axes; the box fade is
// BoxTransitionDistance (cm). The sphere capture: a sphere of InfluenceRadius about location.
TEST_P(EnginePreset, UnrealBoxIsTheUnitBoxUnderScale3DInCentimetres) {
  const Exported e = exportLevel(GetParam(), "unreal");
  const auto world = [](glm::dvec3 u) { return glm::dvec3(u.x, -u.y, u.z) / 100.0; };
  Worst worst;
  for (std::size_t i = 0; i < e.builds.size(); ++i) {
    const nlohmann::json& engines = e.json["probes"][i]["engines"];
    const nlohmann::json& entry = engines["unreal_box_reflection_capture"];
    if (!entry.is_null()) {
      ++worst.entries;
      const glm::dvec3 location = vec3(entry["location"]);
      const glm::dquat rotation = quatXyzw(entry["rotation_xyzw"]);
      EXPECT_NEAR(glm::length(rotation), 1.0, 1e-9);
      std::vector<glm::dvec3> unreal;
      for (const glm::dvec3& c : corners(location, rotation, vec3(entry["scale_3d"])))
        unreal.push_back(world(c));
      worst.corners = std::max(worst.corners,
                               cornerDistance(unreal, worldCorners(sourceBox(e.builds[i], entry))));
      const glm::dvec3 capture = world(location + vec3(entry["capture_offset"]));
      worst.capture =
          std::max(worst.capture, glm::distance(capture, e.scene.probes[i].captureMeters));
      worst.fade =
          std::max(worst.fade, std::abs(entry["box_transition_distance"].get<double>() / 100.0 -
                                        influenceFadeMeters(e.scene.probes[i].influence)));
    }
    const nlohmann::json& sphere = engines["unreal_sphere_reflection_capture"];
    if (!sphere.is_null()) {
      const std::string name = sphere["candidate"].get<std::string>();
      for (const ProxyCandidate& c : e.builds[i].candidates) {
        if (candidateName(c) != name) continue;
        const auto& s = std::get<SphereShape>(c.shape);
        EXPECT_NEAR(glm::distance(world(vec3(sphere["location"])), s.centerMeters), 0.0,
                    kToleranceMeters);
        EXPECT_NEAR(sphere["influence_radius"].get<double>() / 100.0, s.radiiMeters.x,
                    kToleranceMeters);
        EXPECT_NEAR(glm::distance(world(vec3(sphere["location"]) + vec3(sphere["capture_offset"])),
                                  e.scene.probes[i].captureMeters),
                    0.0, kToleranceMeters);
      }
    }
  }
  EXPECT_LE(worst.corners, kToleranceMeters);
  EXPECT_LE(worst.capture, kToleranceMeters);
  EXPECT_LE(worst.fade, kToleranceMeters);
  worst.print("unreal", GetParam().name);
}

// Godot: right-handed, Y up, metres; Godot (x, y, z) is world (x, -z, y). The box is centred on
// the node: local_pos = inverse(node transform) * vertex, inside where |local_pos| <=
// box_extents = size / 2 (scene_forward_lights_inc.glsl / scene.glsl, reflection_process()); the
// cubemap's centre is origin + basis * origin_offset, which Godot clamps to extents - 0.01 per
// axis (ReflectionProbe::set_origin_offset): `exact` is false exactly where that clamp moves it.
TEST_P(EnginePreset, GodotBoxIsCentredOnTheNodeWithOriginOffsetInItsFrame) {
  const Exported e = exportLevel(GetParam(), "godot");
  const auto world = [](glm::dvec3 g) { return glm::dvec3(g.x, -g.z, g.y); };
  Worst worst;
  for (std::size_t i = 0; i < e.builds.size(); ++i) {
    const nlohmann::json& entry = e.json["probes"][i]["engines"]["godot_reflection_probe"];
    if (entry.is_null()) continue;
    ++worst.entries;
    const glm::dvec3 origin = vec3(entry["origin"]);
    const glm::dquat basis = quatXyzw(entry["rotation_xyzw"]);
    const glm::dvec3 extents = vec3(entry["size"]) / 2.0;
    std::vector<glm::dvec3> godot;
    for (const glm::dvec3& c : corners(origin, basis, extents)) godot.push_back(world(c));
    worst.corners =
        std::max(worst.corners, cornerDistance(godot, worldCorners(sourceBox(e.builds[i], entry))));
    // Godot's clamp, as ReflectionProbe::set_origin_offset applies it.
    glm::dvec3 offset = vec3(entry["origin_offset"]);
    bool moved = false;
    for (int a = 0; a < 3; ++a) {
      if (extents[a] - 0.01 < std::abs(offset[a])) {
        offset[a] = (offset[a] < 0 ? -1.0 : 1.0) * (extents[a] - 0.01);
        moved = true;
      }
    }
    EXPECT_EQ(entry["exact"].get<bool>(), !moved) << e.builds[i].probe;
    if (!moved) {
      const glm::dvec3 capture = world(origin + basis * offset);
      worst.capture =
          std::max(worst.capture, glm::distance(capture, e.scene.probes[i].captureMeters));
    }
    worst.fade = std::max(worst.fade, std::abs(entry["blend_distance"].get<double>() -
                                               influenceFadeMeters(e.scene.probes[i].influence)));
    EXPECT_TRUE(entry["box_projection"].get<bool>());
  }
  EXPECT_LE(worst.corners, kToleranceMeters);
  EXPECT_LE(worst.capture, kToleranceMeters);
  EXPECT_LE(worst.fade, kToleranceMeters);
  worst.print("godot", GetParam().name);
}

// Bevy's lookup (environment_map.wesl, compute_cubemap_sample_dir), for the Auto bounds (0.5):
// in the light probe's unit-cube space, the hit of the ray against the cube, from its centre.
// Returned in world axes as the cubemap would be sampled if it had been captured in world axes.
glm::dvec3 bevySampleDirection(const glm::dmat4& lightFromWorld, glm::dvec3 origin,
                               glm::dvec3 direction) {
  const glm::dvec3 o = glm::dvec3(lightFromWorld * glm::dvec4(origin, 1.0));
  const glm::dvec3 d = glm::dvec3(lightFromWorld * glm::dvec4(direction, 0.0));
  double t = std::numeric_limits<double>::max();
  for (int a = 0; a < 3; ++a) {
    for (double bound : {-0.5, 0.5}) {
      const double ta = (bound - o[a]) / d[a];
      if (ta >= 0.0) t = std::min(t, ta);
    }
  }
  return o + d * t;
}

// Bevy: right-handed, Y up, metres; Bevy (x, y, z) is world (x, -z, y). The box is the 1x1x1
// cube under translation, rotation and scale (full size); LightProbe::falloff fades
// falloff * scale / 2 inside each face. `exact` holds exactly where Bevy's own lookup gives the
// true box-projected direction for a cubemap captured at the capture point.
TEST_P(EnginePreset, BevyBoxIsTheUnitCubeUnderItsTransform) {
  const Exported e = exportLevel(GetParam(), "bevy");
  const auto world = [](glm::dvec3 b) { return glm::dvec3(b.x, -b.z, b.y); };
  const auto bevyAxes = [](glm::dvec3 w) { return glm::dvec3(w.x, w.z, -w.y); };
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Worst worst;
  int exactEntries = 0;
  double worstLookupDeg = 0.0;
  for (std::size_t i = 0; i < e.builds.size(); ++i) {
    const nlohmann::json& entry = e.json["probes"][i]["engines"]["bevy_light_probe"];
    if (entry.is_null()) continue;
    ++worst.entries;
    const glm::dvec3 translation = vec3(entry["translation"]);
    const glm::dquat rotation = quatXyzw(entry["rotation_xyzw"]);
    const glm::dvec3 scale = vec3(entry["scale"]);
    std::vector<glm::dvec3> bevy;
    for (const glm::dvec3& c : corners(translation, rotation, scale / 2.0))
      bevy.push_back(world(c));
    worst.corners =
        std::max(worst.corners, cornerDistance(bevy, worldCorners(sourceBox(e.builds[i], entry))));
    const double fade = influenceFadeMeters(e.scene.probes[i].influence);
    const glm::dvec3 falloff = vec3(entry["falloff"]);
    for (int a = 0; a < 3; ++a) {
      worst.fade = std::max(worst.fade,
                            std::abs(falloff[a] * scale[a] / 2.0 - std::min(fade, scale[a] / 2.0)));
    }
    const glm::dvec3 capture = e.scene.probes[i].captureMeters;
    const bool atCentre = entry["capture_at_centre"].get<bool>();
    EXPECT_EQ(atCentre, glm::distance(world(translation), capture) <= 1e-6) << e.builds[i].probe;
    // Bevy's lookup against the ideal one, in Bevy's axes, from points inside the box.
    const glm::dmat4 worldFromLight = glm::translate(glm::dmat4(1.0), translation) *
                                      glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
    const glm::dmat4 lightFromWorld = glm::inverse(worldFromLight);
    double worstDeg = 0.0;
    for (int k = 0; k < 64; ++k) {
      const glm::dvec3 local(0.4 * unit(rng), 0.4 * unit(rng), 0.4 * unit(rng));
      const glm::dvec3 from = glm::dvec3(worldFromLight * glm::dvec4(local, 1.0));
      const glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
      const glm::dvec3 hitLocal = bevySampleDirection(lightFromWorld, from, dir);
      const glm::dvec3 hit = glm::dvec3(worldFromLight * glm::dvec4(hitLocal, 1.0));
      const glm::dvec3 ideal = glm::normalize(hit - bevyAxes(capture));
      const glm::dvec3 sampled = glm::normalize(hitLocal);
      worstDeg = std::max(worstDeg,
                          glm::degrees(std::acos(std::clamp(glm::dot(ideal, sampled), -1.0, 1.0))));
    }
    worstLookupDeg = std::max(worstLookupDeg, worstDeg);
    if (entry["exact"].get<bool>()) {
      ++exactEntries;
      EXPECT_LT(worstDeg, 1e-6) << e.builds[i].probe;
    } else {
      EXPECT_GT(worstDeg, 1e-3) << e.builds[i].probe << ": Bevy's lookup is right, yet not exact";
    }
  }
  EXPECT_LE(worst.corners, kToleranceMeters);
  EXPECT_LE(worst.fade, kToleranceMeters);
  std::printf("bevy %s: %d of %d entries exact in Bevy's own lookup; worst lookup %.1f deg\n",
              GetParam().name.c_str(), exactEntries, worst.entries, worstLookupDeg);
  worst.print("bevy", GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Levels, EnginePreset, ::testing::ValuesIn(levels()),
                         [](const ::testing::TestParamInfo<Level>& p) { return p.param.name; });

}  // namespace
}  // namespace probeproxy
