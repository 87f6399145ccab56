#include "geometry/export/runtime_export.h"

#include "core/scene/file_frame.h"
#include "geometry/export/unit_transform.h"
#include "geometry/scene/json_layout.h"

#include <cmath>
#include <functional>
#include <utility>

namespace probeproxy {

namespace {

using Members = std::vector<std::pair<std::string, JsonLayoutValue>>;

// The shortest decimal that reads back to exactly `value` ("0.0", not the layout's "0e+00").
JsonLayoutValue exact(double value) {
  return value == 0.0 ? jsonCoordinate(0.0) : jsonExactNumber(value);
}

// A file-unit number: rounded to 1e-9 (so 0.3 m in centimetres reads 30.0, not
// 30.000000000000004) only where the rounded number reads back to the same metres; otherwise
// the shortest decimal that reads back exactly.
JsonLayoutValue fileNumber(double value, const std::function<double(double)>& toWorld) {
  const double rounded = jsonRoundedCoordinate(value);
  return toWorld(rounded) == toWorld(value) ? jsonCoordinate(value) : exact(value);
}

class FileWriter {
 public:
  explicit FileWriter(const FileFrame& frame) : frame_(frame) {}

  JsonLayoutValue length(double meters) const {
    return fileNumber(fileLengthFromWorld(frame_, meters),
                      [&](double v) { return worldLengthFromFile(frame_, v); });
  }

  JsonLayoutValue perLength(double perMeter) const {  // k: per metre -> per file unit
    return fileNumber(perMeter * frame_.metersPerUnit,
                      [&](double v) { return v / frame_.metersPerUnit; });
  }

  JsonLayoutValue lengths(glm::dvec3 fileValues) const {
    return jsonArray({length3(fileValues.x), length3(fileValues.y), length3(fileValues.z)});
  }

  JsonLayoutValue point(glm::dvec3 meters) const {
    return lengths(filePointFromWorld(frame_, meters));
  }

  JsonLayoutValue halfExtents(glm::dvec3 meters) const {
    return lengths(fileHalfExtentsFromWorld(frame_, meters));
  }

  JsonLayoutValue rotation(const glm::dquat& worldFromShape) const {
    const glm::dquat q = fileRotationFromWorld(frame_, worldFromShape);
    return jsonArray({exact(q.w), exact(q.x), exact(q.y), exact(q.z)});
  }

  JsonLayoutValue plane(const ProxyPlane& plane) const {
    const glm::dvec3 n = fileDirectionFromWorld(frame_, plane.normal);
    return jsonArray({exact(n.x), exact(n.y), exact(n.z), length(plane.offsetMeters)});
  }

  // The unit transform of the shape as the file spells it, so that a reader in the file's
  // frame needs nothing else; row-major.
  JsonLayoutValue worldToUnit(glm::dvec3 centerMeters, glm::dvec3 extentsMeters,
                              const glm::dquat& worldFromShape) const {
    const glm::dmat4 m = toUnitTransform(filePointFromWorld(frame_, centerMeters),
                                         fileHalfExtentsFromWorld(frame_, extentsMeters),
                                         fileRotationFromWorld(frame_, worldFromShape));
    std::vector<JsonLayoutValue> rows;
    for (int r = 0; r < 4; ++r) {
      rows.push_back(jsonArray({exact(m[0][r]), exact(m[1][r]), exact(m[2][r]), exact(m[3][r])}));
    }
    return jsonArray(std::move(rows), /*oneItemPerLine=*/true);
  }

 private:
  // One coordinate already in file units.
  JsonLayoutValue length3(double fileValue) const {
    return fileNumber(fileValue, [&](double v) { return worldLengthFromFile(frame_, v); });
  }

  FileFrame frame_;
};

JsonLayoutValue upJson(UpAxis up) { return jsonString(up == UpAxis::Y ? "Y" : "Z"); }

JsonLayoutValue boolJson(bool value) {
  JsonLayoutValue v;
  v.scalarText = value ? "true" : "false";
  return v;
}

JsonLayoutValue nullJson() {
  JsonLayoutValue v;
  v.scalarText = "null";
  return v;
}

JsonLayoutValue errorJson(const ErrorFigures& e) {
  return jsonObject({{"median_deg", exact(e.medianDeg)},
                     {"p95_deg", exact(e.p95Deg)},
                     {"max_deg", exact(e.maxDeg)},
                     {"miss_rate", exact(e.missRate)},
                     {"occluded_rate", exact(e.occludedRate)},
                     {"samples", jsonInteger(static_cast<long long>(e.samples))}});
}

JsonLayoutValue boxJson(const BoxShape& box, const FileWriter& w) {
  return jsonObject({{"center", w.point(box.centerMeters)},
                     {"half_extents", w.halfExtents(box.halfExtentsMeters)},
                     {"rotation", w.rotation(box.worldFromBox)}});
}

JsonLayoutValue sphereJson(const SphereShape& sphere, const FileWriter& w) {
  return jsonObject({{"center", w.point(sphere.centerMeters)},
                     {"radii", w.halfExtents(sphere.radiiMeters)},
                     {"rotation", w.rotation(sphere.worldFromSphere)}});
}

JsonLayoutValue influenceJson(const InfluenceVolume& influence, const FileWriter& w) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    return jsonObject({{"kind", jsonString("box")},
                       {"center", w.point(box->centerMeters)},
                       {"half_extents", w.halfExtents(box->halfExtentsMeters)},
                       {"rotation", w.rotation(box->worldFromBox)},
                       {"inner_half_extents", w.halfExtents(box->innerHalfExtentsMeters)}});
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return jsonObject({{"kind", jsonString("sphere")},
                     {"center", w.point(sphere.centerMeters)},
                     {"radius", w.length(sphere.radiusMeters)},
                     {"inner_radius", w.length(sphere.innerRadiusMeters)}});
}

// Engine values: in the engine's unit, rounded to 1e-9 of it.
JsonLayoutValue engineVec3(glm::dvec3 v) {
  return jsonArray({jsonCoordinate(v.x), jsonCoordinate(v.y), jsonCoordinate(v.z)});
}

JsonLayoutValue engineQuat(const glm::dquat& q) {
  return jsonArray(
      {jsonCoordinate(q.x), jsonCoordinate(q.y), jsonCoordinate(q.z), jsonCoordinate(q.w)});
}

Members sourceMembers(const EngineSource& source) {
  return {{"candidate", jsonString(source.candidate)},
          {"kept_proxy", boolJson(source.keptProxy)},
          {"error", errorJson(source.error)}};
}

template <class T>
JsonLayoutValue optionalEngine(const std::optional<T>& engine,
                               const std::function<Members(const T&)>& params) {
  if (!engine) return nullJson();
  Members members = sourceMembers(engine->source);
  for (auto& member : params(*engine)) members.push_back(std::move(member));
  return jsonObject(std::move(members), /*oneItemPerLine=*/true);
}

JsonLayoutValue godotJson(const std::optional<GodotReflectionProbe>& godot) {
  return optionalEngine<GodotReflectionProbe>(godot, [](const GodotReflectionProbe& p) -> Members {
    return {{"origin", engineVec3(p.origin)},
            {"rotation_xyzw", engineQuat(p.rotation)},
            {"size", engineVec3(p.size)},
            {"origin_offset", engineVec3(p.originOffset)},
            {"blend_distance", jsonCoordinate(p.blendDistance)},
            {"max_distance", jsonCoordinate(p.maxDistance)},
            {"box_projection", boolJson(p.boxProjection)},
            {"exact", boolJson(p.exact)}};
  });
}

JsonLayoutValue enginesJson(const RuntimeEngines& e) {
  return jsonObject(
      {{"unity_reflection_probe", optionalEngine<UnityReflectionProbe>(
                                      e.unity,
                                      [](const UnityReflectionProbe& p) -> Members {
                                        return {{"position", engineVec3(p.position)},
                                                {"center", engineVec3(p.center)},
                                                {"size", engineVec3(p.size)},
                                                {"blend_distance", jsonCoordinate(p.blendDistance)},
                                                {"box_projection", boolJson(p.boxProjection)},
                                                {"importance", jsonInteger(p.importance)}};
                                      })},
       {"unity_hdrp_reflection_probe",
        optionalEngine<UnityHdrpReflectionProbe>(
            e.unityHdrp,
            [](const UnityHdrpReflectionProbe& p) -> Members {
              Members m = {{"position", engineVec3(p.position)},
                           {"rotation_xyzw", engineQuat(p.rotation)},
                           {"influence_shape", jsonString(p.sphere ? "sphere" : "box")}};
              if (p.sphere) {
                m.push_back({"sphere_radius", jsonCoordinate(p.sphereRadius)});
                m.push_back({"sphere_blend_distance", jsonCoordinate(p.blendDistancePositive.x)});
              } else {
                m.push_back({"box_size", engineVec3(p.boxSize)});
                m.push_back({"box_blend_distance_positive", engineVec3(p.blendDistancePositive)});
                m.push_back({"box_blend_distance_negative", engineVec3(p.blendDistanceNegative)});
              }
              m.push_back({"capture_position", engineVec3(p.capturePosition)});
              m.push_back({"proxy_position", engineVec3(p.proxyPosition)});
              m.push_back({"proxy_rotation_xyzw", engineQuat(p.proxyRotation)});
              m.push_back({"proxy_size", engineVec3(p.proxySize)});
              return m;
            })},
       {"unreal_box_reflection_capture",
        optionalEngine<UnrealBoxReflectionCapture>(
            e.unrealBox,
            [](const UnrealBoxReflectionCapture& p) -> Members {
              return {{"location", engineVec3(p.location)},
                      {"rotation_xyzw", engineQuat(p.rotation)},
                      {"scale_3d", engineVec3(p.scale3D)},
                      {"capture_offset", engineVec3(p.captureOffset)},
                      {"box_transition_distance", jsonCoordinate(p.boxTransitionDistance)}};
            })},
       {"unreal_sphere_reflection_capture",
        optionalEngine<UnrealSphereReflectionCapture>(
            e.unrealSphere,
            [](const UnrealSphereReflectionCapture& p) -> Members {
              return {{"location", engineVec3(p.location)},
                      {"influence_radius", jsonCoordinate(p.influenceRadius)},
                      {"capture_offset", engineVec3(p.captureOffset)}};
            })},
       {"godot_reflection_probe", godotJson(e.godot)},
       {"godot4_reflection_probe", godotJson(e.godot4)},
       {"bevy_light_probe",
        optionalEngine<BevyLightProbe>(e.bevy,
                                       [](const BevyLightProbe& p) -> Members {
                                         return {{"translation", engineVec3(p.translation)},
                                                 {"rotation_xyzw", engineQuat(p.rotation)},
                                                 {"scale", engineVec3(p.scale)},
                                                 {"falloff", engineVec3(p.falloff)},
                                                 {"parallax_correction", jsonString("auto")},
                                                 {"capture_at_centre", boolJson(p.captureAtCentre)},
                                                 {"exact", boolJson(p.exact)}};
                                       })},
       {"eevee_reflection_cubemap",
        optionalEngine<EeveeReflectionCubemap>(
            e.eevee,
            [](const EeveeReflectionCubemap& p) -> Members {
              return {{"location", engineVec3(p.location)},
                      {"rotation_xyzw", engineQuat(p.rotation)},
                      {"scale", engineVec3(p.scale)},
                      {"influence_type", jsonString(p.sphere ? "ELIPSOID" : "BOX")},
                      {"influence_distance", jsonCoordinate(1.0)},
                      {"falloff", jsonCoordinate(p.falloff)},
                      {"use_custom_parallax", boolJson(true)},
                      {"parallax_type", jsonString("BOX")},
                      {"parallax_distance", jsonCoordinate(p.parallaxDistance)}};
            })}},
      /*oneItemPerLine=*/true);
}

JsonLayoutValue probeJson(const RuntimeProbe& p, const FileWriter& w) {
  Members members{{"name", jsonString(p.name)},
                  {"capture", w.point(p.captureMeters)},
                  {"kind", jsonString(std::string(methodName(p.method)))},
                  {"candidate", jsonString(p.candidate)}};
  if (p.kPerMeter) members.emplace_back("k", w.perLength(*p.kPerMeter));
  if (p.box) members.emplace_back("box", boxJson(*p.box, w));
  if (p.sphere) members.emplace_back("sphere", sphereJson(*p.sphere, w));
  if (p.box) {
    members.emplace_back(
        "world_to_unit",
        w.worldToUnit(p.box->centerMeters, p.box->halfExtentsMeters, p.box->worldFromBox));
  } else if (p.sphere) {
    members.emplace_back(
        "world_to_unit",
        w.worldToUnit(p.sphere->centerMeters, p.sphere->radiiMeters, p.sphere->worldFromSphere));
  }
  members.emplace_back("planes_count", jsonInteger(p.planesCount));
  std::vector<JsonLayoutValue> planes, vertices, triangles;
  for (const ProxyPlane& plane : p.convex.planes) planes.push_back(w.plane(plane));
  for (const glm::dvec3& v : p.convex.verticesMeters) vertices.push_back(w.point(v));
  for (const glm::uvec3& t : p.convex.triangles) {
    triangles.push_back(jsonArray({jsonInteger(t.x), jsonInteger(t.y), jsonInteger(t.z)}));
  }
  members.emplace_back("planes", jsonArray(std::move(planes), /*oneItemPerLine=*/true));
  members.emplace_back("vertices", jsonArray(std::move(vertices), /*oneItemPerLine=*/true));
  members.emplace_back("triangles", jsonArray(std::move(triangles), /*oneItemPerLine=*/true));
  members.emplace_back("mesh_is_display_only", boolJson(p.meshIsDisplayOnly));
  members.emplace_back("influence", influenceJson(p.influence, w));
  members.emplace_back(
      "blend", jsonObject({{"enlighten", jsonObject({{"epsilon", exact(p.enlighten.epsilon)},
                                                     {"box", boxJson(p.enlighten.box, w)}})}}));
  members.emplace_back("error", errorJson(p.error));
  members.emplace_back("engines", enginesJson(p.engines));
  return jsonObject(std::move(members), /*oneItemPerLine=*/true);
}

}  // namespace

std::string runtimeExportJson(const RuntimeExport& runtime) {
  const FileWriter writer(FileFrame{runtime.fileUp, runtime.metersPerUnit});
  std::vector<JsonLayoutValue> probes;
  for (const RuntimeProbe& probe : runtime.probes) probes.push_back(probeJson(probe, writer));
  const JsonLayoutValue root =
      jsonObject({{kRuntimeExportFormatId, jsonInteger(kRuntimeExportVersion)},
                  {"up", upJson(runtime.fileUp)},
                  {"meters_per_unit", exact(runtime.metersPerUnit)},
                  {"mesh_file", jsonString(kProxiesGlbName)},
                  {"probes", jsonArray(std::move(probes), /*oneItemPerLine=*/true)}},
                 /*oneItemPerLine=*/true);
  return layoutJson(root);
}

}  // namespace probeproxy
