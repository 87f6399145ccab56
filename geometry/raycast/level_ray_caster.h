#pragma once
// First-hit ray casting against the level with Embree. Built once from a LevelMesh, then
// immutable: every query is const and safe to call from many threads at once.

#include "geometry/level/level_mesh.h"
#include "geometry/raycast/ray.h"

#include <memory>
#include <span>

namespace probeproxy {

class LevelRayCaster {
 public:
  // Copies the level's vertices and triangles into Embree's layout; `level` may go away after.
  explicit LevelRayCaster(const LevelMesh& level);
  ~LevelRayCaster();
  LevelRayCaster(const LevelRayCaster&) = delete;
  LevelRayCaster& operator=(const LevelRayCaster&) = delete;

  RayHit firstHit(const Ray& ray) const;

  // The level triangle nearest `point` in any direction (Embree's point query, exact to the
  // float vertices), none (infinite distance) when none lies within `radiusMeters`. Ties go to
  // the lower triangle index, so the answer is the same every run.
  SurfacePoint nearestTriangle(glm::dvec3 point, double radiusMeters) const;

  // The axis-aligned bounds of the level's vertices, world frame (empty level: both 0).
  glm::dvec3 boundsMinMeters() const;
  glm::dvec3 boundsMaxMeters() const;

  // LevelMesh::facesOneSided: a hit on a face's back is a hit from inside solid or the void.
  bool facesOneSided() const { return facesOneSided_; }

  // hits[i] answers rays[i]; the batch is split over all cores (TBB). Results do not depend
  // on the number of threads. `coherent` tells Embree the rays share an origin (depth cubes).
  void firstHits(std::span<const Ray> rays, std::span<RayHit> hits, bool coherent = false) const;

  // One ray at a time on the calling thread: the baseline the batched path is measured against.
  void firstHitsOneByOne(std::span<const Ray> rays, std::span<RayHit> hits) const;

 private:
  struct Embree;
  std::unique_ptr<Embree> embree_;
  bool facesOneSided_ = false;
};

}  // namespace probeproxy
