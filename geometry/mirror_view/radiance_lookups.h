#pragma once
// The RadianceLookup (mirror_view_reconstruction.h) of each way to fetch a probe's cubemap for
// a reflected ray. Each keeps references to its arguments: they must outlive it.

#include "core/cube/cubemap.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/pointcloud/point_cloud_splat.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/mirror_view/mirror_view_reconstruction.h"
#include "geometry/raycast/level_ray_caster.h"

namespace probeproxy {

// A per-pixel method (docs/methods_and_measures.md "Methods": infinite, cheap_k, sphere, aabb, obb,
// convex) through the one prepared-proxy interface (prepareProxy + lookupScalar, the float shader
// ports), then a seam-aware bilinear fetch of the cubemap's sharpest level along d = P - C.
RadianceLookup proxyRadianceLookup(const Cubemap& cube, const ProxyShape& shape,
                                   glm::dvec3 captureMeters);

// The perfect proxy: d* = H - C with H the true first hit of (x, r) in the level (Embree), or r
// where the ray leaves the level (sky); never a miss. What
// this reconstructs is limited only by the cubemap's resolution, the bilinear fetch and the
// renders' noise: the best any proxy can do with this cubemap.
RadianceLookup trueHitRadianceLookup(const Cubemap& cube, const LevelRayCaster& level,
                                     glm::dvec3 captureMeters);

// The mixing step (mixing_plane, raster_convex): the cube corrected for the view's reflected
// camera E' (correctCubemap), fetched bilinearly at its sharpest level along r (x lies on the
// ray from E' along r, as the mirror's reflected view ray). A miss where the texel holding r
// is a missed one (the seed's red).
RadianceLookup correctedCubeRadianceLookup(const CorrectedCubemap& corrected);

// Hodgman's proxy-free `pointcloud` method: the cloud splatted around x, sampled along r
// (point_cloud_splat.h). A direction no splat or fill reached is a miss.
RadianceLookup pointCloudRadianceLookup(const PointCloud& cloud, const PointCloudOptions& options);

}  // namespace probeproxy
