#pragma once
// Cubemaps as six image files, one per face, named by core/cube/cube_face.h's face names.

#include "core/cube/cubemap.h"

#include <filesystem>
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

// One image holding the whole cube, its layout told by its aspect ratio: 4:3 a horizontal
// cross, 3:4 a vertical cross (core/cube/cube_cross.h), 2:1 equirectangular
// (core/cube/equirect.h; resampled to faces of width / 4). Reads what readCubemap reads, the
// same way (sRGB 8/16-bit to linear). A path holding {face} is read as six files by
// readCubemap. Returns the cube with its full mip chain. Throws InputError naming the file on
// a missing or unreadable image, or one of another aspect ratio or a size the layout cannot
// divide (e.g. "cubemap image is 1000 x 600 pixels: expected a 4:3 horizontal cross, a 3:4
// vertical cross or a 2:1 equirectangular image").
Cubemap readCubemapImage(const std::filesystem::path& path);

enum class CubemapImageLayout { HorizontalCross, VerticalCross, Equirect };

// One mip level as one RGB float EXR, atomically: a cross of the level's faces, or an
// equirect image 4N wide (N the level's face size). Throws std::out_of_range on a missing
// level, InputError when the file cannot be written.
void writeCubemapImage(const Cubemap& cube, const std::filesystem::path& file,
                       CubemapImageLayout layout, int level = 0);

}  // namespace probeproxy
