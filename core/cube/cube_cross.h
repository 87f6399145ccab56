#pragma once
// Cubemaps as one cross-shaped image: the cube unfolded and seen from inside, every face in
// the orientation core/cube/cube_face.h gives it (a photograph, not mirrored), so the image
// is continuous across every edge two neighbouring cells share.
//
//   horizontal cross (4 x 3 cells)      vertical cross (3 x 4 cells)
//        .   pz   .    .                     .   pz   .
//        px  ny   nx   py                    px  ny   nx
//        .   nz   .    .                     .   nz   .
//                                            .   py'  .
//
// py' is py turned 180 degrees (its top is -Z, its right -X), so that it continues nz's
// bottom edge; every other cell is its face as it is. Empty cells are black (0). The middle
// row, left to right, is what a camera turning right sees: px ny nx py; pz (+Y at the top)
// sits on ny's top edge and nz (-Y at the top) on its bottom edge.
//
// Against the usual engine cross (Y up: -X +Z +X -Z in the middle row, +Y above, -Y below,
// the layout of DirectX-style cube faces): that cross comes from a left-handed Y-up world.
// Through world_frame.h's Y-up conversion (a Y-up point (x, y, z) is our (x, -z, y)), our
// cross reads +X +Z -X -Z, +Y above, -Y below: the same picture with X mirrored, because our
// world is right-handed. A left-handed Y-up engine's cross is read unchanged if its (x, y, z)
// is our (-x, -z, y): its +Z (the centre cell) is our -Y, its +Y our +Z, its +X our -X.

#include "core/cube/cubemap.h"
#include "core/image/rgb_image.h"

namespace probeproxy {

enum class CrossLayout { Horizontal, Vertical };

// One mip level as a cross image of 4N x 3N (horizontal) or 3N x 4N (vertical) pixels.
// Throws std::out_of_range on a missing level.
RgbImage crossFromCube(const Cubemap& cube, CrossLayout layout, int level = 0);

// The six faces (level 0 only) of a cross image. Throws std::invalid_argument unless the
// image is exactly 4N x 3N (horizontal) or 3N x 4N (vertical) for some N >= 1.
Cubemap cubeFromCross(const RgbImage& image, CrossLayout layout);

}  // namespace probeproxy
