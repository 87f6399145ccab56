#include "geometry/raycast/level_ray_caster.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace probeproxy {

struct LevelRayCaster::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  // Embree works in float. Vertices and ray origins are stored relative to the centre of the
  // level's bounds, so a level 10 km from the world origin is cast as precisely as one at it.
  glm::dvec3 originMeters{0.0};
  glm::dvec3 boundsMinMeters{0.0}, boundsMaxMeters{0.0};
};

namespace {

void throwOnEmbreeError(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("Embree failed to ") + what + " (error " +
                             std::to_string(static_cast<int>(error)) + ")");
  }
}

RTCRayHit toEmbree(const Ray& ray, glm::dvec3 levelOrigin) {
  RTCRayHit rh{};
  const glm::vec3 origin(ray.originMeters - levelOrigin);
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = ray.direction.x;
  rh.ray.dir_y = ray.direction.y;
  rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = ray.tMin;
  rh.ray.tfar = ray.tMax;
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

RayHit fromEmbree(const RTCRayHit& rh) {
  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.t = rh.ray.tfar;
  hit.triangle = rh.hit.primID;
  // Embree's Ng is (v0 - v2) x (v1 - v0) = (v1 - v0) x (v2 - v0): counter-clockwise winding.
  hit.geometricNormal = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
  return hit;
}

// Embree's stream call takes a batch this size or smaller; TBB hands out whole batches, so the
// split, and so every result, is the same whatever the thread count.
constexpr std::size_t kBatch = 256;

}  // namespace

LevelRayCaster::LevelRayCaster(const LevelMesh& level) : embree_(std::make_unique<Embree>()) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()),
      hi(-std::numeric_limits<double>::infinity());
  for (const glm::vec3& p : level.positionsMeters)
    lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  if (!level.positionsMeters.empty()) {
    embree_->originMeters = 0.5 * (lo + hi);
    embree_->boundsMinMeters = lo;
    embree_->boundsMaxMeters = hi;
  }

  embree_->device = rtcNewDevice(nullptr);
  if (embree_->device == nullptr) throw std::runtime_error("Embree could not create a device");
  // Robust mode: rays that graze shared edges of a closed room must not slip through the crack.
  embree_->scene = rtcNewScene(embree_->device);
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree reads 16 bytes per vertex: the buffer gets one float of padding.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               level.positionsMeters.size() + 1));
  for (std::size_t i = 0; i < level.positionsMeters.size(); ++i) {
    const glm::vec3 local(glm::dvec3(level.positionsMeters[i]) - embree_->originMeters);
    vertices[3 * i + 0] = local.x;
    vertices[3 * i + 1] = local.y;
    vertices[3 * i + 2] = local.z;
  }
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), level.triangles.size()));
  for (std::size_t i = 0; i < level.triangles.size(); ++i) {
    indices[3 * i + 0] = level.triangles[i].x;
    indices[3 * i + 1] = level.triangles[i].y;
    indices[3 * i + 2] = level.triangles[i].z;
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(embree_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(embree_->scene);
  throwOnEmbreeError(embree_->device, "build the level's ray-casting structure");
}

LevelRayCaster::~LevelRayCaster() {
  if (embree_->scene != nullptr) rtcReleaseScene(embree_->scene);
  if (embree_->device != nullptr) rtcReleaseDevice(embree_->device);
}

glm::dvec3 LevelRayCaster::boundsMinMeters() const { return embree_->boundsMinMeters; }
glm::dvec3 LevelRayCaster::boundsMaxMeters() const { return embree_->boundsMaxMeters; }

RayHit LevelRayCaster::firstHit(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh = toEmbree(ray, embree_->originMeters);
  rtcIntersect1(embree_->scene, &context, &rh);
  return fromEmbree(rh);
}

void LevelRayCaster::firstHits(std::span<const Ray> rays, std::span<RayHit> hits,
                               bool coherent) const {
  if (hits.size() != rays.size()) throw std::invalid_argument("firstHits: one hit per ray");
  const std::size_t batches = (rays.size() + kBatch - 1) / kBatch;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batches), [&](const auto& range) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags =
        coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    RTCRayHit stream[kBatch];
    for (std::size_t b = range.begin(); b != range.end(); ++b) {
      const std::size_t first = b * kBatch;
      const std::size_t count = std::min(kBatch, rays.size() - first);
      for (std::size_t i = 0; i < count; ++i)
        stream[i] = toEmbree(rays[first + i], embree_->originMeters);
      rtcIntersect1M(embree_->scene, &context, stream, static_cast<unsigned>(count),
                     sizeof(RTCRayHit));
      for (std::size_t i = 0; i < count; ++i) hits[first + i] = fromEmbree(stream[i]);
    }
  });
}

void LevelRayCaster::firstHitsOneByOne(std::span<const Ray> rays, std::span<RayHit> hits) const {
  if (hits.size() != rays.size()) throw std::invalid_argument("firstHitsOneByOne: one hit per ray");
  for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = firstHit(rays[i]);
}

}  // namespace probeproxy
