#pragma once
// Which influence volumes may reach a small square of the floor, answered from square columns
// over the level. The fades' scans ask it for every walked cell at every camera height, and an
// open level has thousands of volumes, each reaching a few dozen metres: testing every volume
// for every cell made the scan grow with the floor times the probes.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

class VolumeColumns {
 public:
  // lo[v], hi[v]: volume v's bounds (only x and y are used).
  VolumeColumns(std::span<const glm::dvec3> lo, std::span<const glm::dvec3> hi,
                double columnMeters = 4.0);
  // The volumes whose columns meet the square [lo, hi], each once, in increasing order: every
  // volume whose bounds meet it, and some that do not (test the bounds).
  void near(glm::dvec2 lo, glm::dvec2 hi, std::vector<std::uint32_t>& out) const;

 private:
  glm::ivec2 columnOf(glm::dvec2 p) const;
  glm::dvec2 origin_{0.0};
  double columnMeters_;
  glm::ivec2 count_{0};
  std::vector<std::uint32_t> first_;    // per column, where its volumes start in volumes_
  std::vector<std::uint32_t> volumes_;  // column by column, each column's in increasing order
};

}  // namespace probeproxy
