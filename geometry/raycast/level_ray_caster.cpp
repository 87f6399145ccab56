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
  // The geometry's own buffers (Embree's, alive as long as the scene): point queries read them.
  const float* vertices = nullptr;
  const unsigned* indices = nullptr;
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

// Real-Time Collision Detection (Ericson 2005), 5.1.5: the triangle's Voronoi regions in turn.
glm::dvec3 closestPointOnTriangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double sum = va + vb + vc;
  // A degenerate triangle (real levels hold them) has no inside: its nearest vertex stands in.
  if (!(sum > 0.0)) {
    const double da = glm::dot(ap, ap), db = glm::dot(bp, bp), dc = glm::dot(cp, cp);
    return da <= db && da <= dc ? a : (db <= dc ? b : c);
  }
  return a + ab * (vb / sum) + ac * (vc / sum);
}

struct PointQueryState {
  const float* vertices;
  const unsigned* indices;
  glm::dvec3 point;  // relative to the level's centre, as the vertices are
  SurfacePoint nearest;
};

bool onTriangleInReach(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<PointQueryState*>(args->userPtr);
  const unsigned* t = state->indices + 3 * std::size_t(args->primID);
  auto vertex = [&](unsigned i) {
    const float* v = state->vertices + 3 * std::size_t(i);
    return glm::dvec3(v[0], v[1], v[2]);
  };
  const glm::dvec3 nearest =
      closestPointOnTriangle(state->point, vertex(t[0]), vertex(t[1]), vertex(t[2]));
  const double distance = glm::length(nearest - state->point);
  SurfacePoint& best = state->nearest;
  if (distance > best.distanceMeters ||
      (distance == best.distanceMeters && args->primID >= best.triangle))
    return false;
  best = {distance, args->primID};
  if (distance >= args->query->radius) return false;
  args->query->radius = static_cast<float>(distance);  // nothing farther need be visited
  return true;
}

// Embree's stream call takes a batch this size or smaller; TBB hands out whole batches, so the
// split, and so every result, is the same whatever the thread count.
constexpr std::size_t kBatch = 256;

}  // namespace

LevelRayCaster::LevelRayCaster(const LevelMesh& level)
    : embree_(std::make_unique<Embree>()), facesOneSided_(level.facesOneSided) {
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
  embree_->vertices = vertices;
  embree_->indices = indices;
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

SurfacePoint LevelRayCaster::nearestTriangle(glm::dvec3 point, double radiusMeters) const {
  PointQueryState state{embree_->vertices, embree_->indices, point - embree_->originMeters, {}};
  if (embree_->indices == nullptr) return state.nearest;
  RTCPointQuery query{};
  query.x = static_cast<float>(state.point.x);
  query.y = static_cast<float>(state.point.y);
  query.z = static_cast<float>(state.point.z);
  query.radius = static_cast<float>(std::min(radiusMeters, 1e30));
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(embree_->scene, &query, &context, onTriangleInReach, &state);
  if (state.nearest.distanceMeters > radiusMeters) return {};
  return state.nearest;
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
