#pragma once
// Fresnel attenuation of a reflection: how much of the incoming light a surface reflects at a
// given angle. Bjorke, GPU Gems ch. 19 writes it as
//   fres = KrMin + (Kr - KrMin) * pow(1 - abs(dot(V, N)), FresExp)
// which is Schlick's approximation (Schlick 1994) for KrMin = F0, Kr = 1, FresExp = 5.

namespace probeproxy {

// Schlick: F = F0 + (1 - F0) * (1 - cosTheta)^5. f0 is the reflectance at normal incidence
// (about 0.04 for dielectrics, the base colour's channel for metals), in [0, 1]; cosTheta is
// dot(view, normal) of unit vectors: its sign is ignored (Bjorke's abs) and it is clamped to
// [0, 1], so a slightly denormalized input never leaves [f0, 1]. A NaN input gives NaN.
float fresnelSchlick(float f0, float cosTheta);

}  // namespace probeproxy
