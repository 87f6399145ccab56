#pragma once
// The level as Hodgman's coloured point cloud, made from what a probe already has: one point
// per texel of its cubemap's sharpest level, where that texel's centre ray first hits the
// level (Embree), with the texel's radiance. Emissive (or diffuse) surfaces look the same
// from any side, so the colour the probe saw is the colour every shading point sees.

#include "core/cube/cubemap.h"
#include "core/pointcloud/point_cloud_splat.h"
#include "geometry/raycast/level_ray_caster.h"

namespace probeproxy {

// Origin = the capture point. Each point is the disc with its texel's footprint area on the
// surface: radius (t / N) / sqrt(cos incidence), t the distance, N the face size, the cosine
// kept above 0.2. Texels
// that see no level (sky) give no point.
PointCloud probePointCloud(const LevelRayCaster& level, const Cubemap& cube,
                           glm::dvec3 captureMeters);

}  // namespace probeproxy
