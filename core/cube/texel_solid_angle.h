#pragma once
// The solid angle a cube texel covers on the unit sphere: texels near a face's corners cover
// less than those at its centre (by up to 3^(3/2) = 5.2 times), so integrals over a cubemap
// must weight each texel by it.

namespace probeproxy {

// Exact solid angle (steradians) of texel (col, row) of an N x N face, the same for every
// face. The six faces' texels sum to 4 pi. Uses the area of the face rectangle
// [x0, x1] x [y0, y1] (face plane at distance 1) seen from the centre:
//   A(x, y) = atan2(x y, sqrt(x^2 + y^2 + 1)),  omega = A(x1, y1) - A(x0, y1) - A(x1, y0) + A(x0,
//   y0).
double texelSolidAngle(int col, int row, int faceSize);

}  // namespace probeproxy
