#pragma once
// A reference mirror view (the suite's `mirror_views/<name>.json`): a pinhole camera at eye
// height looking at a floor that Cycles rendered as a perfect mirror. World frame (Z up),
// metres, as the Blender suite writes it (scripts/scenes/suite/mirror_views.py).
//
// Camera model (the one scripts/scenes/verify_convention.py checks against Cycles): pixel
// (col, row) of a width x height image, row 0 at the top, looks along
//   forward + (2u - 1) tan(fov_x / 2) right + (1 - 2v) tan(fov_x / 2) (height / width) up,
//   u = (col + 0.5) / width, v = (row + 0.5) / height, right = forward x up.

#include "core/scene/scene.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace probeproxy {

struct MirrorView {
  std::string name;
  std::string probe;                    // the probe whose cubemap reconstructs this view
  std::filesystem::path image;          // the Cycles render with the mirror floor (linear EXR)
  std::filesystem::path positionImage;  // same camera, floor not mirrored, first-hit world
                                        // positions (metres); `<name>_position.exr`
  int width = 0, height = 0;            // pixels
  glm::dvec3 positionMeters{0.0};       // the eye
  glm::dvec3 forward{1, 0, 0};          // unit
  glm::dvec3 up{0, 0, 1};               // unit, orthogonal to forward
  double fovXDeg = 70.0;                // horizontal field of view, degrees
  ReflectionPlane mirrorPlane;          // the mirror floor
};

// Reads and checks `<name>.json`; image paths are resolved against its folder. Throws
// InputError(file, "<JSON path>: <what was expected>") on a missing or wrong field.
MirrorView readMirrorView(const std::filesystem::path& file);

// Unit world direction through the centre of pixel (col, row) (the model above).
glm::dvec3 mirrorViewRay(const MirrorView& view, int col, int row);

// The scene's mirror views: `mirror_views/*.json` beside the scene file, sorted by file name
// (none when the folder does not exist).
std::vector<std::filesystem::path> mirrorViewFiles(const Scene& scene);

// The probe a view names. Throws InputError naming the view's file when the scene has none.
const Probe& mirrorViewProbe(const Scene& scene, const MirrorView& view);

}  // namespace probeproxy
