#include "geometry/mirror_view/mirror_view_reconstruction.h"

#include "core/errors/input_error.h"
#include "core/image/write_exr.h"
#include "core/measures/error_images.h"

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace probeproxy {

namespace {

// A world-position render holds exactly 0 where the ray left to the sky.
bool onPlane(const RgbImage& positions, int col, int row, const ReflectionPlane& plane) {
  const glm::vec3 p = positions.at(col, row);
  if (p == glm::vec3(0.0f)) return false;
  return std::abs(glm::dot(glm::dvec3(p) - plane.pointMeters, plane.normal)) < 1e-3;
}

void checkSize(const RgbImage& image, const MirrorView& view, const std::filesystem::path& file) {
  if (image.width != view.width || image.height != view.height) {
    throw InputError(file, "is " + std::to_string(image.width) + " x " +
                               std::to_string(image.height) + " pixels, the mirror view says " +
                               std::to_string(view.width) + " x " + std::to_string(view.height));
  }
}

}  // namespace

MirrorViewReference loadMirrorViewReference(const MirrorView& view) {
  MirrorViewReference ref;
  ref.view = view;
  ref.cycles = readRgbImage(view.image);
  checkSize(ref.cycles, view, view.image);
  const RgbImage positions = readRgbImage(view.positionImage);
  checkSize(positions, view, view.positionImage);

  const std::size_t n = static_cast<std::size_t>(view.width) * view.height;
  ref.mask.assign(n, 0);
  ref.xMeters.assign(n, glm::dvec3(0.0));
  ref.reflected.assign(n, glm::dvec3(0.0));
  const ReflectionPlane& plane = view.mirrorPlane;
  for (int row = 0; row < view.height; ++row) {
    for (int col = 0; col < view.width; ++col) {
      bool floor = true;
      for (int dr = -1; dr <= 1 && floor; ++dr) {
        for (int dc = -1; dc <= 1 && floor; ++dc) {
          const int c = col + dc, r = row + dr;
          if (c < 0 || r < 0 || c >= view.width || r >= view.height) continue;
          floor = onPlane(positions, c, r, plane);
        }
      }
      const glm::dvec3 ray = mirrorViewRay(view, col, row);
      const double towards = glm::dot(ray, plane.normal);
      if (!floor || towards >= 0.0) continue;
      const double t = glm::dot(plane.pointMeters - view.positionMeters, plane.normal) / towards;
      if (!(t > 0.0)) continue;
      const std::size_t i = static_cast<std::size_t>(row) * view.width + col;
      ref.mask[i] = 1;
      ref.xMeters[i] = view.positionMeters + t * ray;
      ref.reflected[i] = glm::reflect(ray, plane.normal);
    }
  }
  return ref;
}

MirrorViewReconstruction reconstructMirrorView(const MirrorViewReference& ref,
                                               const RadianceLookup& lookup) {
  const std::size_t n = ref.mask.size();
  MirrorViewReconstruction out;
  out.rgb.assign(n * 3, 0.0f);
  out.miss.assign(n, 0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    if (!ref.mask[i]) return;
    const std::optional<glm::vec3> radiance = lookup(ref.xMeters[i], ref.reflected[i]);
    if (!radiance) {
      out.miss[i] = 1;
      return;
    }
    for (int k = 0; k < 3; ++k) out.rgb[i * 3 + k] = (*radiance)[k];
  });
  out.error = imageError(ref.cycles.rgb, out.rgb, ref.mask, out.miss);
  return out;
}

void writeMirrorViewImages(const std::filesystem::path& folder, const std::string& stem,
                           const MirrorViewReference& ref, const MirrorViewReconstruction& rec) {
  std::filesystem::create_directories(folder);
  const int w = ref.view.width, h = ref.view.height;
  const std::vector<float> absError = absErrorPerPixel(ref.cycles.rgb, rec.rgb, ref.mask, rec.miss);
  writeErrorComparisonPng(
      folder / (stem + "_heatmap.png"),
      {w, h, ref.cycles.rgb, rec.rgb, absError, ref.mask, rec.miss,
       static_cast<float>(rec.error.peak), static_cast<float>(rec.error.peak / 4.0)});
  writeMissMaskPng(folder / (stem + "_miss.png"), w, h, ref.mask, rec.miss);
  writeExr(folder / (stem + ".exr"), w, h, {"R", "G", "B"}, rec.rgb);
}

}  // namespace probeproxy
