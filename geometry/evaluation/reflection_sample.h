#pragma once
// Reflection samples (docs/methods_and_measures.md, "Measures"): a point x on a level surface with
// normal n, seen from a camera at e, reflecting r = reflect(x - e, n), and where that ray really
// lands. World frame (Z up), metres.

#include <glm/vec3.hpp>

#include <cstdint>
#include <string_view>

namespace probeproxy {

enum class SampleSet {
  MirrorFloor,  // upward-facing surfaces inside the influence volume, seen by cameras at eye
                // height as a player sees them (reflection_samples.cpp)
  AllSurfaces,  // every surface inside the influence volume, same cameras
};

std::string_view sampleSetName(SampleSet set);  // "mirror_floor", "all_surfaces"

struct ReflectionSample {
  glm::dvec3 xMeters{0.0};        // shading point, on a level surface
  glm::dvec3 normal{0, 0, 1};     // unit, facing the camera
  glm::dvec3 eyeMeters{0.0};      // the camera that sees x
  glm::dvec3 reflected{0, 0, 1};  // unit r = reflect(normalize(x - e), n)
  glm::dvec3 trueHitMeters{0.0};  // H: first level hit of (x, r); meaningless when hitsSky
  bool hitsSky = false;           // (x, r) leaves the level: the ideal lookup is r itself
  bool occluded = false;          // H (or the sky along r) is hidden from the capture point
};

}  // namespace probeproxy
