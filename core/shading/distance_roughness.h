#pragma once
// Distance-based roughness: a glossy lookup into a parallax-corrected cubemap picks its mip
// from the roughness (the Enlighten documentation's mipFromRoughness,
// core/cube/cubemap_sampling.h), but the cubemap was filtered as seen from the capture point C, not
// from the shading point x. A reflection lobe leaving x reaches the proxy hit P with a footprint
// whose size grows with |P - x|; C sees that footprint at distance |P - C|. So a shading point
// close to the wall it reflects sees a sharper reflection than the probe's filtered mip, and one
// far from it a blurrier one (Lagarde & Zanuttini's glossy discussion; the "distance-based
// roughness" engines offer).
//
// Derivation (comment in distance_roughness.cpp): the roughness that C would need to see the
// same footprint is
//   roughnessSeenFromCapture = roughness * sqrt(|P - x| / |P - C|),   clamped to [0, 1].

#include <glm/vec3.hpp>

namespace probeproxy {

// hitFromShadingMeters = |P - x|, hitFromCaptureMeters = |P - C| (both >= 0). Returns the
// roughness in [0, 1] to pass to mipFromRoughness. Roughness 0 (a mirror) stays 0; P = C (a
// footprint C cannot resolve) gives the roughest, 1, unless the roughness is 0; x = C leaves
// it unchanged. Never NaN for finite, non-negative inputs; a NaN input gives NaN, as
// mipFromRoughness then reports.
float roughnessSeenFromCapture(float roughness, float hitFromShadingMeters,
                               float hitFromCaptureMeters);

// The same from the points themselves (world frame, metres).
float roughnessSeenFromCapture(float roughness, glm::vec3 shadingMeters, glm::vec3 proxyHitMeters,
                               glm::vec3 captureMeters);

}  // namespace probeproxy
