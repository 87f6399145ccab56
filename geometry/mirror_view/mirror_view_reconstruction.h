#pragma once
// Validation against an independent renderer (docs/methods_and_measures.md "Measures"): the
// reflection a mirror floor shows, rebuilt from a probe's cubemap by a correction method, against
// the Cycles render of the same view.
//
// For every pixel whose camera ray meets the mirror floor: x = where the ray meets the mirror
// plane, r = the ray reflected about the plane's normal, and the method's radiance for (x, r)
// (radiance_lookups.h) is the pixel. Pixels that see anything else are left out (the mask).

#include "core/image/rgb_image.h"
#include "core/measures/image_error.h"
#include "geometry/mirror_view/mirror_view.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

namespace probeproxy {

// What a correction method shows at a mirror point x (world metres) looking along r (unit):
// linear RGB radiance, or none for a miss (the seeds' red pixel). Called from many threads
// at once: it must be safe for that (read-only state).
using RadianceLookup = std::function<std::optional<glm::vec3>(glm::dvec3 xMeters, glm::dvec3 r)>;

// A view with everything each method needs, loaded once.
struct MirrorViewReference {
  MirrorView view;
  RgbImage cycles;                    // the Cycles render (mirror floor)
  std::vector<std::uint8_t> mask;     // 1 = the pixel's whole filter footprint sees the floor
  std::vector<glm::dvec3> xMeters;    // per pixel: the point on the mirror plane (mask only)
  std::vector<glm::dvec3> reflected;  // per pixel: unit reflected direction (mask only)
};

// The floor pixels of `<name>_position.exr`: the first hit lies on the mirror plane (within a
// millimetre), and so do the hits of all 8 neighbours (Cycles filters the colour render over
// about a pixel, so a pixel next to a wall mixes wall into the floor's reflection; leaving
// those out measures the method, not the filter). Throws InputError when an image is missing
// or not width x height.
MirrorViewReference loadMirrorViewReference(const MirrorView& view);

struct MirrorViewReconstruction {
  std::vector<float> rgb;          // interleaved linear RGB, 0 outside the mask and on misses
  std::vector<std::uint8_t> miss;  // 1 = masked pixel the method missed
  ImageErrorFigures error;         // against reference.cycles over reference.mask
};

// Every masked pixel through `lookup`, in parallel; deterministic (one pixel per call).
MirrorViewReconstruction reconstructMirrorView(const MirrorViewReference& reference,
                                               const RadianceLookup& lookup);

// Writes `<stem>_heatmap.png` (error_images.h, scaleMax = a quarter of the view's PSNR peak),
// `<stem>_miss.png` and `<stem>.exr` (the reconstruction) into `folder` (created if needed).
void writeMirrorViewImages(const std::filesystem::path& folder, const std::string& stem,
                           const MirrorViewReference& reference,
                           const MirrorViewReconstruction& reconstruction);

}  // namespace probeproxy
