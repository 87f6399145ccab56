#pragma once
// Disjoint sets over 0..n-1, with path halving. Each set's representative is its lowest
// index, so grouping (flat hull regions, coincident corners) comes out the same on every run.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace probeproxy::fit {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace probeproxy::fit
