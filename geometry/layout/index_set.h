#pragma once
// A set of floor-sample or floor-cell indices, compressed: a CRoaring bitmap. Samples and cells
// are numbered row by row (walkable_floor.h sorts cells by row, then column), so the floor a
// capture point sees is a few runs of indices per row, and a run container holds each in 4
// bytes: on open ground, where a candidate sees most of the level, its sets cost bytes per row
// of floor instead of 4 bytes per sample.

#include <roaring/roaring.hh>

#include <cstddef>
#include <cstdint>

namespace probeproxy {

using IndexSet = Roaring;

// Calls f(index) for each index of the set, ascending.
template <class F>
void forEachIndex(const IndexSet& set, F&& f) {
  roaring_uint32_iterator_t it;
  roaring_init_iterator(&set.roaring, &it);
  for (; it.has_value; roaring_advance_uint32_iterator(&it)) f(it.current_value);
}

// Made once and then only read: runs where they are smaller, no spare capacity.
inline void compact(IndexSet& set) {
  set.runOptimize();
  set.shrinkToFit();
}

inline std::size_t countOf(const IndexSet& set) {
  return static_cast<std::size_t>(set.cardinality());
}

}  // namespace probeproxy
