#pragma once
// Mixing at a point of interest (Lagarde & Zanuttini 2012, "point of interest-based" approach): the
// weighted sum of the probes' cubemaps, texel by texel, face by face, for every mip level, as the
// seed blends each mip of its preconvolved cubemaps. The weights come from
// core/blend/blend_weights.h.
//
// Every cube must have the same level-0 face size and the same number of levels; cubes of
// different sizes are refused (std::invalid_argument naming both sizes), not resampled: the
// caller names the file (the seed mixes at the largest size; resampling is left to the tool
// that bakes the probes).

#include "core/cube/cubemap.h"

#include <span>

namespace probeproxy {

struct WeightedCubemap {
  const Cubemap* cube = nullptr;  // not owned
  float weight = 0.0f;            // the weights need not sum to 1; they are used as given
};

// Throws std::invalid_argument on no cube, a null cube, or cubes whose sizes differ.
Cubemap mixCubemaps(std::span<const WeightedCubemap> cubes);

// The same into `mixed`, reusing its storage when it already has the cubes' layout (a runtime
// mixing every frame allocates once). Same throws; `mixed` must not be one of the inputs.
void mixCubemapsInto(std::span<const WeightedCubemap> cubes, Cubemap& mixed);

// Whether two cubes can be mixed: same level count and the same face size at level 0.
bool sameCubemapLayout(const Cubemap& a, const Cubemap& b);

}  // namespace probeproxy
