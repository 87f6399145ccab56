#include "core/pointcloud/point_cloud_splat.h"

#include "core/pointcloud/octahedral.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace probeproxy {

namespace {

constexpr float kPi = 3.14159265358979f;

std::size_t index(int col, int row, int size) { return static_cast<std::size_t>(row) * size + col; }

// The seed's separable blur along one direction (dc, dr), weighted by |alpha|, writing only
// into texels no disc covered.
void fillPass(OctahedralMap& map, int dc, int dr, int radius) {
  const int n = map.size;
  const std::vector<glm::vec4> source = map.texels;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      glm::vec4& out = map.texels[index(col, row, n)];
      if (out.w > 0.0f) continue;
      glm::vec3 sum(0.0f);
      float weight = 0.0f;
      for (int k = -radius; k <= radius; ++k) {
        int c = col + k * dc, r = row + k * dr;
        wrapOctahedralTexel(c, r, n);
        const glm::vec4& s = source[index(c, r, n)];
        const float w = std::abs(s.w);
        sum += w * glm::vec3(s);
        weight += w;
      }
      if (weight > 0.0f) out = glm::vec4(sum / weight, -weight / (2.0f * radius + 1.0f));
    }
  }
}

}  // namespace

OctahedralMap splatPointCloud(const PointCloud& cloud, glm::dvec3 centreMeters,
                              const PointCloudOptions& options) {
  const int n = options.mapSize;
  if (n < 2 || options.blurRadiusTexels < 0 || options.maxDiscRadiusTexels < 0) {
    throw std::invalid_argument("splatPointCloud: map size below 2 or a negative radius");
  }
  OctahedralMap map{n, std::vector<glm::vec4>(static_cast<std::size_t>(n) * n, glm::vec4(0.0f))};
  std::vector<float> nearest(map.texels.size(), std::numeric_limits<float>::infinity());
  const glm::vec3 centre(centreMeters - cloud.originMeters);
  const float texelSolidAngle = 4.0f * kPi / static_cast<float>(n * n);
  const float texelAngle = std::sqrt(texelSolidAngle);
  for (const RadiancePoint& p : cloud.points) {
    const glm::vec3 d = p.fromOriginMeters - centre;
    const float distSq = glm::dot(d, d);
    if (!(distSq > 0.0f)) continue;
    const float dist = std::sqrt(distSq);
    const float facing = std::abs(glm::dot(p.normal, d)) / dist;
    // The disc's solid angle seen from the centre, and its angular radius.
    const float solidAngle = kPi * p.radiusMeters * p.radiusMeters * facing / distSq;
    const float alpha = solidAngle / texelSolidAngle;
    const float radiusTexels = std::min(std::sqrt(solidAngle / kPi) / texelAngle,
                                        static_cast<float>(options.maxDiscRadiusTexels));
    const glm::vec2 uv = octahedralUvFromDirection(d) * static_cast<float>(n);
    const int reach = static_cast<int>(std::ceil(radiusTexels));
    const int c0 = std::min(static_cast<int>(uv.x), n - 1),
              r0 = std::min(static_cast<int>(uv.y), n - 1);
    for (int dr = -reach; dr <= reach; ++dr) {
      for (int dc = -reach; dc <= reach; ++dc) {
        // The texel holding the point always takes it; others when their centre is in the disc.
        if (dr != 0 || dc != 0) {
          const float ex = c0 + dc + 0.5f - uv.x, ey = r0 + dr + 0.5f - uv.y;
          if (ex * ex + ey * ey > radiusTexels * radiusTexels) continue;
        }
        int c = c0 + dc, r = r0 + dr;
        wrapOctahedralTexel(c, r, n);
        const std::size_t i = index(c, r, n);
        if (dist >= nearest[i]) continue;
        nearest[i] = dist;
        map.texels[i] = glm::vec4(p.rgb, std::max(alpha, 1e-6f));
      }
    }
  }
  // The seed's four passes: horizontal, vertical, diagonal, the other diagonal.
  if (options.blurRadiusTexels > 0) {
    fillPass(map, 1, 0, options.blurRadiusTexels);
    fillPass(map, 0, 1, options.blurRadiusTexels);
    fillPass(map, 1, 1, options.blurRadiusTexels);
    fillPass(map, 1, -1, options.blurRadiusTexels);
  }
  return map;
}

std::optional<glm::vec3> sampleOctahedralMap(const OctahedralMap& map, glm::vec3 direction) {
  const int n = map.size;
  const glm::vec2 p = octahedralUvFromDirection(direction) * static_cast<float>(n) - 0.5f;
  const int c0 = static_cast<int>(std::floor(p.x)), r0 = static_cast<int>(std::floor(p.y));
  const float fx = p.x - static_cast<float>(c0), fy = p.y - static_cast<float>(r0);
  glm::vec3 sum(0.0f);
  float weight = 0.0f;
  for (int k = 0; k < 4; ++k) {
    int c = c0 + (k & 1), r = r0 + (k >> 1);
    const float w = ((k & 1) ? fx : 1.0f - fx) * ((k >> 1) ? fy : 1.0f - fy);
    wrapOctahedralTexel(c, r, n);
    const glm::vec4& t = map.texels[index(c, r, n)];
    if (t.w == 0.0f || w <= 0.0f) continue;
    sum += w * glm::vec3(t);
    weight += w;
  }
  if (!(weight > 0.0f)) return std::nullopt;
  return sum / weight;
}

std::optional<glm::vec3> pointCloudRadiance(const PointCloud& cloud, glm::dvec3 xMeters,
                                            glm::vec3 r, const PointCloudOptions& options) {
  return sampleOctahedralMap(splatPointCloud(cloud, xMeters, options), r);
}

}  // namespace probeproxy
