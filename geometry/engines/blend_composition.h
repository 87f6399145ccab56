#pragma once
// The ways engines compose the probes that reach a shaded point, given each probe's own weight
// (its fade at the point) in the order the engine visits them. Each returns the weights that
// end up on screen and the sky / ambient fallback's share.

#include "geometry/engines/engine_model.h"

#include <algorithm>
#include <numeric>
#include <span>
#include <vector>

namespace probeproxy {

// Indices 0 .. count - 1 by `key(i)` ascending, ties in index order: the order an engine visits
// its probes in, fixed once for the level.
template <typename Key>
std::vector<int> orderedBy(std::size_t count, Key key) {
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  return order;
}

// `fadeOf(i)` of each probe in `order`, the positive ones, in that order.
template <typename FadeOf>
std::vector<ProbeFade> fadesInOrder(std::span<const int> order, FadeOf fadeOf) {
  std::vector<ProbeFade> fades;
  for (const int i : order) {
    const double fade = fadeOf(static_cast<std::size_t>(i));
    if (fade > 0.0) fades.push_back({i, fade});
  }
  return fades;
}

// Front to back: each probe takes its fade of what is left (Unreal's
// ImageBasedReflections.a *= 1 - DistanceAlpha; Unity's deferred probes drawn over each other,
// back to front, are the same in the reverse order). The fallback gets what is left at the end.
EngineBlend frontToBack(std::span<const ProbeFade> ordered);

// Fill to one: each probe takes its fade, cut to what the ones before left (HDRP's
// UpdateLightingHierarchyWeights, EEVEE's accumulate_light); the fallback the rest. Once the
// sum reaches `fullAt` nothing more is added, the fallback included (EEVEE stops at 0.999).
EngineBlend fillToOne(std::span<const ProbeFade> ordered, double fullAt = 1.0);

// Up to the largest fade so far: each probe takes max(0, fade - accumulated), the accumulated
// weight becoming the largest fade seen (Godot 4's reflection_blend = max(0, blend -
// reflection_accum.a)); the fallback 1 - the largest fade.
EngineBlend upToLargestFade(std::span<const ProbeFade> ordered);

// Normalized: fade / sum of fades; the fallback only where every fade is 0 (Godot 3's
// reflection_accum.rgb / reflection_accum.a, else the environment).
EngineBlend normalizedFades(std::span<const ProbeFade> fades);

}  // namespace probeproxy
