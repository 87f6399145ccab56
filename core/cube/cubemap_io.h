#pragma once
// Cubemaps as six image files, one per face, named by core/cube/cube_face.h's face names.

#include "core/cube/cubemap.h"

#include <string>

namespace probeproxy {

// `pattern` holds `{face}`, e.g. "cubemaps/corridor_a_{face}.exr" -> corridor_a_px.exr ...
// Reads any format OpenImageIO reads (EXR, HDR, PNG, ...): the first three channels as RGB
// (a one-channel image as grey). 8/16-bit images that OpenImageIO reports in sRGB (PNG, JPEG)
// are converted to linear; float formats (EXR, HDR) are taken as linear already. Every face must
// be square and all six the same size. Returns the cube with its full mip chain built.
// Throws InputError naming the file on a missing, unreadable, non-square, wrongly sized,
// wrongly channelled or non-finite face, or (naming the pattern) on a pattern without {face}.
Cubemap readCubemap(const std::string& pattern);

// Writes one mip level as six RGB float EXRs (channels R, G, B), each atomically
// (core/image/write_exr.h). Throws std::out_of_range on a missing level,
// std::invalid_argument on a pattern without {face}, InputError when a file cannot be written.
void writeCubemap(const Cubemap& cube, const std::string& pattern, int level = 0);

}  // namespace probeproxy
