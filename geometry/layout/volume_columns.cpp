#include "geometry/layout/volume_columns.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy {

VolumeColumns::VolumeColumns(std::span<const glm::dvec3> lo, std::span<const glm::dvec3> hi,
                             double columnMeters)
    : columnMeters_(columnMeters) {
  if (lo.empty()) return;
  glm::dvec2 top(std::numeric_limits<double>::lowest());
  origin_ = glm::dvec2(std::numeric_limits<double>::max());
  for (std::size_t v = 0; v < lo.size(); ++v) {
    origin_ = glm::min(origin_, glm::dvec2(lo[v]));
    top = glm::max(top, glm::dvec2(hi[v]));
  }
  count_ = glm::ivec2(glm::floor((top - origin_) / columnMeters_)) + 1;
  const std::size_t columns = static_cast<std::size_t>(count_.x) * count_.y;
  // Two passes (count, then fill) so the lists sit end to end, each in volume order.
  std::vector<std::uint32_t> sizes(columns, 0);
  const auto forEachColumn = [&](std::size_t v, auto&& visit) {
    const glm::ivec2 a = columnOf(lo[v]), b = columnOf(hi[v]);
    for (int y = a.y; y <= b.y; ++y)
      for (int x = a.x; x <= b.x; ++x) visit(static_cast<std::size_t>(y) * count_.x + x);
  };
  for (std::size_t v = 0; v < lo.size(); ++v) forEachColumn(v, [&](std::size_t c) { ++sizes[c]; });
  first_.assign(columns + 1, 0);
  for (std::size_t c = 0; c < columns; ++c) first_[c + 1] = first_[c] + sizes[c];
  volumes_.resize(first_.back());
  std::vector<std::uint32_t> filled(first_.begin(), first_.end() - 1);
  for (std::size_t v = 0; v < lo.size(); ++v)
    forEachColumn(v, [&](std::size_t c) { volumes_[filled[c]++] = static_cast<std::uint32_t>(v); });
}

glm::ivec2 VolumeColumns::columnOf(glm::dvec2 p) const {
  // Points off the volumes' extent fall in the edge columns, whose volumes are a superset.
  return glm::ivec2(glm::clamp(glm::floor((p - origin_) / columnMeters_), glm::dvec2(0.0),
                               glm::dvec2(count_ - 1)));
}

void VolumeColumns::near(glm::dvec2 lo, glm::dvec2 hi, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (volumes_.empty()) return;
  const glm::ivec2 a = columnOf(lo), b = columnOf(hi);
  for (int y = a.y; y <= b.y; ++y)
    for (int x = a.x; x <= b.x; ++x) {
      const std::size_t c = static_cast<std::size_t>(y) * count_.x + x;
      out.insert(out.end(), volumes_.begin() + first_[c], volumes_.begin() + first_[c + 1]);
    }
  if (a != b) {
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
}

}  // namespace probeproxy
