#pragma once
// Blend weights of the probes at a point of interest, behind one interface for both schemes:
//
// - Lagarde (Lagarde & Zanuttini 2012, bonus slides): each volume's normalized distance a
// (core/blend/
//   influence_factor.h: 0 in the inner range, 1 at the outer boundary). A probe weighs
//   (1 - a) / a, normalized over the N most influential (smallest a). For two volumes this is
//   exactly the seed's pseudo-code ((1 - a/SumIW) * (1 - a)/InvSumIW, normalized); for three or
//   more it keeps the seed's rule "100% at the inner range whatever the number of overlapping
//   primitives" without the pseudo-code's early-out, which jumps at the inner boundary. So:
//   0% at the outer boundary, 100% inside an inner range, and a smaller volume inside a larger
//   one dominates wherever it is relatively deeper. Where inner ranges overlap (the seed forbids
//   it) the smallest volume takes 100%.
// - Enlighten (the Enlighten documentation): 1 / (epsilon + distSq to the box), the N closest
// boxes.
//
// Keeping only N: a hard cut would pop when the N-th and the (N+1)-th swap, so each kept
// probe's weight fades to 0 as it gets as far as the (N+1)-th (Lagarde: min(1 - a,
// (a_next - a) / 0.1), a_next = the (N+1)-th smallest a, 1 when fewer volumes cover the point;
// Enlighten: times clamp(log2(epsilon + distSq_next) - log2(epsilon + distSq), 0, 1)). With N
// or fewer candidates nothing fades. Ties order by key, then smaller volume, then probe index,
// so the result is deterministic.

#include "core/scene/influence_volume.h"

#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace probeproxy {

enum class BlendScheme { Lagarde, Enlighten };

// "lagarde", "enlighten"
std::string_view blendSchemeName(BlendScheme scheme);
std::optional<BlendScheme> blendSchemeFromName(std::string_view name);

inline constexpr int kDefaultMaxBlendProbes =
    4;  // Lagarde & Zanuttini 2012: "We set the limit to 4"
inline constexpr double kLagardeFadeWidth = 0.1;  // normalized distance over which the N-th fades

struct BlendOptions {
  BlendScheme scheme = BlendScheme::Lagarde;
  int maxProbes = kDefaultMaxBlendProbes;  // N >= 1
};

struct ProbeWeight {
  int probe = 0;        // index into the volumes passed in (the scene's probe order)
  double weight = 0.0;  // in (0, 1]
};

// The probes that contribute at the point and their weights, which sum to 1 (to rounding);
// ordered by decreasing weight, then probe index; zero weights left out. Empty when no volume
// covers the point (core/blend/influence_factor.h coversPoint), whatever the scheme: outside
// every influence volume no probe applies (Lagarde & Zanuttini 2012). Inside, Enlighten weighs
// every volume, covering or not, as the Enlighten documentation does. Throws std::invalid_argument
// on maxProbes < 1.
std::vector<ProbeWeight> blendWeights(std::span<const InfluenceVolume> volumes,
                                      glm::dvec3 pointMeters, const BlendOptions& options = {});

}  // namespace probeproxy
