#pragma once
// Hodgman, "Imperfect Environment Maps": a proxy-free reflection. The level as a
// cloud of coloured points is splatted into an octahedral map (octahedral.h) around the
// shading point, each point a disc whose alpha is the solid angle it covers; holes are filled
// by an alpha-weighted blur; the lookup is that map sampled along r.
//
// Differences from the seed, for a mirror reflection rather than blobby glossy IBL: a depth
// test (the nearest disc covering a texel wins, as the seed's comments suggest against light
// leaking), discs as wide as their solid angle instead of single texels, and the blur only
// fills texels no disc covered (sign bit as in the seed: negative alpha = from the blur), so
// what was splatted stays sharp.

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <span>
#include <vector>

namespace probeproxy {

struct RadiancePoint {
  glm::vec3 fromOriginMeters{0.0f};  // position relative to the cloud's origin, metres
  glm::vec3 normal{0, 0, 1};         // unit surface normal (facing either way)
  glm::vec3 rgb{0.0f};               // linear radiance the surface emits towards the probe
  float radiusMeters = 0.0f;         // the disc the point stands for
};

struct PointCloud {
  glm::dvec3 originMeters{0.0};  // world frame; points are stored relative to it (precision)
  std::vector<RadiancePoint> points;
};

struct PointCloudOptions {
  int mapSize = 64;             // N: the octahedral map is N x N texels
  int blurRadiusTexels = 2;     // each of the seed's four blur passes averages 2 r + 1 texels
  int maxDiscRadiusTexels = 6;  // a point nearer than this covers no more (cost bound)
};

// The map around one point: rgb and alpha per texel, row 0 at the top. alpha > 0: coverage
// (solid angle of the winning disc / solid angle of a texel) of a splatted texel; alpha < 0:
// filled by the blur (its magnitude the blur's weight); 0: nothing (a miss).
struct OctahedralMap {
  int size = 0;
  std::vector<glm::vec4> texels;
};

// Splat then fill: the whole per-shading-point pipeline up to the map.
OctahedralMap splatPointCloud(const PointCloud& cloud, glm::dvec3 centreMeters,
                              const PointCloudOptions& options = {});

// Bilinear over the four texels around the direction, among those with data (weights
// renormalized); none (a miss) when none has. Crosses the square's edges (wrapOctahedralTexel).
std::optional<glm::vec3> sampleOctahedralMap(const OctahedralMap& map, glm::vec3 direction);

// splatPointCloud + sampleOctahedralMap: the `pointcloud` method's radiance for (x, r).
std::optional<glm::vec3> pointCloudRadiance(const PointCloud& cloud, glm::dvec3 xMeters,
                                            glm::vec3 r, const PointCloudOptions& options = {});

}  // namespace probeproxy
