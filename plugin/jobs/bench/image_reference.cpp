#include "plugin/jobs/bench/image_reference.h"

#include "core/cube/cubemap_io.h"

namespace probeproxy::jobs {

std::optional<ImageReference> imageReference(const Scene& scene, const Probe& probe) {
  if (!probe.cubemap) return std::nullopt;
  ImageReference ref;
  for (const std::filesystem::path& file : mirrorViewFiles(scene)) {
    MirrorView view = readMirrorView(file);
    if (view.probe == probe.name) ref.views.push_back(loadMirrorViewReference(view));
  }
  if (ref.views.empty()) return std::nullopt;
  ref.cube = readCubemapImage(scene.file.parent_path() / *probe.cubemap);
  return ref;
}

double meanPsnrDb(
    const std::vector<MirrorViewReference>& views,
    const std::function<RadianceLookup(const MirrorViewReference&)>& lookupFor,
    const std::function<void(const MirrorViewReference&, const MirrorViewReconstruction&)>& seen) {
  double sum = 0.0;
  for (const MirrorViewReference& view : views) {
    const MirrorViewReconstruction reconstruction = reconstructMirrorView(view, lookupFor(view));
    if (seen) seen(view, reconstruction);
    sum += reconstruction.error.psnrDb;
  }
  return sum / static_cast<double>(views.size());
}

}  // namespace probeproxy::jobs
