#pragma once
// What `probeproxy bench` measures psnr_db on: a probe's Cycles cubemap and its reference
// mirror views (the scene's mirror_views/ folder).

#include "core/cube/cubemap.h"
#include "core/scene/scene.h"
#include "geometry/mirror_view/mirror_view_reconstruction.h"

#include <functional>
#include <optional>
#include <vector>

namespace probeproxy::jobs {

struct ImageReference {
  Cubemap cube;
  std::vector<MirrorViewReference> views;  // at least one
};

// None when the scene has no views of this probe or the probe no cubemap (psnr_db is then
// null). Throws InputError for a view or cubemap that cannot be read.
std::optional<ImageReference> imageReference(const Scene& scene, const Probe& probe);

// Mean PSNR over the views of the reflection rebuilt with the lookup each view is given.
// `seen` gets each view's reconstruction too (to write its pictures without rebuilding it).
double meanPsnrDb(const std::vector<MirrorViewReference>& views,
                  const std::function<RadianceLookup(const MirrorViewReference&)>& lookupFor,
                  const std::function<void(const MirrorViewReference&,
                                           const MirrorViewReconstruction&)>& seen = {});

}  // namespace probeproxy::jobs
