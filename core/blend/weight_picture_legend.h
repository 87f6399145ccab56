#pragma once
// The weight picture as a reader needs it: the slice, and under it a legend naming each probe's
// colour, what the white and grey outlines and the squares are, the slice's height and blend
// scheme, and a scale bar.

#include "core/blend/weight_picture.h"
#include "core/image/rgb8_canvas.h"
#include "core/scene/scene.h"

#include <span>
#include <string>
#include <string_view>

namespace probeproxy {

// `probeNames[i]` names probe i's colour (probeColour(i)); `title` heads the legend.
Rgb8Canvas weightPictureWithLegend(const WeightPicture& picture,
                                   std::span<const std::string> probeNames, std::string_view title);

// The scene's probes at height zMeters, named, their capture points marked, titled with the
// height and the blend scheme: what `blend --weights-png` and the demo write.
Rgb8Canvas sceneWeightPicture(const Scene& scene, double zMeters, const BlendOptions& options);

}  // namespace probeproxy
