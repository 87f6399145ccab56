#pragma once
// The talk's top-down picture of blend weights (Lagarde & Zanuttini 2012, "Each color is an
// influence volume and the intensity of Red, Green or Blue represents the final contribution"): a
// horizontal slice of a level's influence volumes, each probe a colour, each pixel the
// weight-summed colour of the probes there; the volumes' outer boundaries in white, their inner
// ranges in grey, uncovered space black, and optional markers (the probes' capture points) as small
// white squares with a black centre. North (+y) up, +x right.

#include "core/blend/blend_weights.h"

#include <glm/gtc/type_precision.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

struct WeightPicture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb8;  // (row * width + col) * 3 + channel, row 0 at the top (north)
  glm::dvec2 minMeters{0.0};       // world x, y of the bottom-left pixel's outer corner
  double metersPerPixel = 0.0;
};

// The colour of probe i (8-bit RGB): red, green, blue first, as in the talk, then others.
glm::u8vec3 probeColour(int probe);

// The slice at height zMeters over the volumes' bounds plus a 0.5 m margin, the longer side
// `longSidePixels` wide. Throws std::invalid_argument on no volume or longSidePixels < 16.
WeightPicture renderWeightPicture(std::span<const InfluenceVolume> volumes, double zMeters,
                                  const BlendOptions& options = {}, int longSidePixels = 800,
                                  std::span<const glm::dvec3> markersMeters = {});

}  // namespace probeproxy
