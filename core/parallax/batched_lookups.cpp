#include "core/parallax/batched_lookups.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

// Built with -fno-math-errno -fno-trapping-math (core/CMakeLists.txt): sqrtf and the selects
// around divisions vectorize only then (-fopt-info-vec). Neither changes a result: errno is
// never read, FP exceptions never trap. -ffp-contract=off keeps FMA out of the AVX2 clone, so
// every CPU gets the same bits as the scalar ports. Never -ffast-math: the box code relies on x/0 =
// +-inf and on NaN failing every comparison.

// On x86-64 with GCC or Clang each kernel is also compiled for AVX2 (8 floats per vector) and
// picked at load time (ifunc); other CPUs run the SSE2 baseline. No -march flag needed.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
#define PROBEPROXY_KERNEL __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define PROBEPROXY_KERNEL
#endif

namespace probeproxy {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr std::size_t kBlock = 256;  // rays per block in the convex kernel: fits in L1

// Every kernel starts with these: plain restrict pointers, so the vectorizer sees no aliasing.
#define PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out)  \
  const float* __restrict xs = (rays).xMeters.data();  \
  const float* __restrict ys = (rays).yMeters.data();  \
  const float* __restrict zs = (rays).zMeters.data();  \
  const float* __restrict rxs = (rays).dirX.data();    \
  const float* __restrict rys = (rays).dirY.data();    \
  const float* __restrict rzs = (rays).dirZ.data();    \
  float* __restrict dxs = (out).dirX.data();           \
  float* __restrict dys = (out).dirY.data();           \
  float* __restrict dzs = (out).dirZ.data();           \
  std::uint8_t* __restrict misses = (out).miss.data(); \
  const std::size_t n = (rays).size()

// d = (x - C) + r t, with t = +inf for a miss. A hit needs d nonzero and finite; t = +inf (or
// NaN) makes d inf or NaN, so one test on max(|dx|, |dy|, |dz|) covers every miss. All masks stay
// float comparisons: mixing bool widths keeps GCC from vectorizing the loop.
inline void finish(float* __restrict dxs, float* __restrict dys, float* __restrict dzs,
                   std::uint8_t* __restrict misses, std::size_t i, float px, float py, float pz,
                   float rx, float ry, float rz, float t) {
  const float dx = px + rx * t, dy = py + ry * t, dz = pz + rz * t;
  const float size = std::max(std::max(std::fabs(dx), std::fabs(dy)), std::fabs(dz));
  const bool hit = (size > 0.0f) & (size < kInf);
  dxs[i] = hit ? dx : 0.0f;
  dys[i] = hit ? dy : 0.0f;
  dzs[i] = hit ? dz : 0.0f;
  misses[i] = hit ? 0 : 1;
}

// The exit distance along one axis of a box [lo, hi] (relative to the point p): the far plane
// the ray moves towards (the Enlighten documentation's back-face cull), none when it is parallel.
// The division runs for every lane (0/0 is NaN there) and the select drops it: no branch.
inline float slab(float lo, float hi, float p, float r) {
  const float toPlane = r > 0.0f ? hi - p : lo - p;
  const float t = toPlane / r;
  return r != 0.0f ? t : kInf;
}

}  // namespace

PROBEPROXY_KERNEL void infiniteBatch(const RaysSoA& rays, const LookupsSoA& out) {
  PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out);
  (void)xs, (void)ys, (void)zs;  // d = r wherever the point is
#pragma GCC ivdep                // outputs never overlap inputs (batched_lookups.h)
  for (std::size_t i = 0; i < n; ++i)
    finish(dxs, dys, dzs, misses, i, 0.0f, 0.0f, 0.0f, rxs[i], rys[i], rzs[i], 1.0f);
}

PROBEPROXY_KERNEL void cheapKBatch(const CheapKConstants& c, const RaysSoA& rays,
                                   const LookupsSoA& out) {
  PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out);
  const float k = c.kPerMeter, cx = c.captureMeters.x, cy = c.captureMeters.y,
              cz = c.captureMeters.z;
#pragma GCC ivdep  // outputs never overlap inputs (batched_lookups.h)
  for (std::size_t i = 0; i < n; ++i) {
    // d = K (x - C) + R, written as (K (x - C)) + R * 1.
    const float rSize = std::fabs(rxs[i]) + std::fabs(rys[i]) + std::fabs(rzs[i]);
    const float t = rSize > 0.0f ? 1.0f : kInf;  // a zero r is a miss, whatever k (x - C) is
    finish(dxs, dys, dzs, misses, i, k * (xs[i] - cx), k * (ys[i] - cy), k * (zs[i] - cz), rxs[i],
           rys[i], rzs[i], t);
  }
}

PROBEPROXY_KERNEL void sphereBatch(const SphereConstants& s, const RaysSoA& rays,
                                   const LookupsSoA& out) {
  PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out);
  const glm::mat3& m = s.lightingFromWorld;
  const float m00 = m[0][0], m01 = m[1][0], m02 = m[2][0];  // row-major names: m_rowcol
  const float m10 = m[0][1], m11 = m[1][1], m12 = m[2][1];
  const float m20 = m[0][2], m21 = m[1][2], m22 = m[2][2];
  const float ox = s.captureInLighting.x, oy = s.captureInLighting.y, oz = s.captureInLighting.z;
  const float cx = s.captureMeters.x, cy = s.captureMeters.y, cz = s.captureMeters.z;
  const float outer = 1.0f + s.insideToleranceLighting, outer2 = outer * outer;
#pragma GCC ivdep  // outputs never overlap inputs (batched_lookups.h)
  for (std::size_t i = 0; i < n; ++i) {
    const float px = xs[i] - cx, py = ys[i] - cy, pz = zs[i] - cz;
    const float rx = rxs[i], ry = rys[i], rz = rzs[i];
    const float lx = m00 * px + m01 * py + m02 * pz + ox;
    const float ly = m10 * px + m11 * py + m12 * pz + oy;
    const float lz = m20 * px + m21 * py + m22 * pz + oz;
    const float ux = m00 * rx + m01 * ry + m02 * rz;
    const float uy = m10 * rx + m11 * ry + m12 * rz;
    const float uz = m20 * rx + m21 * ry + m22 * rz;
    const float a = ux * ux + uy * uy + uz * uz;
    const float b = lx * ux + ly * uy + lz * uz;
    const float pp = lx * lx + ly * ly + lz * lz;
    const float c = pp - 1.0f;
    const float disc = b * b - a * c;
    const float root = std::sqrt(disc > 0.0f ? disc : 0.0f);
    const float far = (root - b) / a;
    const float farStable = -c / (b + root);
    const float inside = b <= 0.0f ? far : farStable;  // the far root without cancellation
    const float onSurface = far > 0.0f ? far : 0.0f;
    const float exit = c < 0.0f ? inside : onSurface;
    const float t = (a > 0.0f) & (pp <= outer2) ? exit : kInf;
    finish(dxs, dys, dzs, misses, i, px, py, pz, rx, ry, rz, t);
  }
}

PROBEPROXY_KERNEL void aabbBatch(const AabbConstants& box, const RaysSoA& rays,
                                 const LookupsSoA& out) {
  PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out);
  const float cx = box.captureMeters.x, cy = box.captureMeters.y, cz = box.captureMeters.z;
  const float lox = box.boxMinFromCapture.x, loy = box.boxMinFromCapture.y,
              loz = box.boxMinFromCapture.z;
  const float hix = box.boxMaxFromCapture.x, hiy = box.boxMaxFromCapture.y,
              hiz = box.boxMaxFromCapture.z;
  const float tol = 1e-3f;  // kInsideToleranceMeters
#pragma GCC ivdep           // outputs never overlap inputs (batched_lookups.h)
  for (std::size_t i = 0; i < n; ++i) {
    const float px = xs[i] - cx, py = ys[i] - cy, pz = zs[i] - cz;
    const float rx = rxs[i], ry = rys[i], rz = rzs[i];
    // How far x lies outside the box (<= 0 inside), as one float so the mask is one compare.
    const float outside =
        std::max(std::max(std::max(lox - px, px - hix), std::max(loy - py, py - hiy)),
                 std::max(loz - pz, pz - hiz));
    const float tx = slab(lox, hix, px, rx), ty = slab(loy, hiy, py, ry),
                tz = slab(loz, hiz, pz, rz);
    float t = tx < ty ? tx : ty;
    t = t < tz ? t : tz;
    t = t > 0.0f ? t : 0.0f;
    t = outside <= tol ? t : kInf;
    finish(dxs, dys, dzs, misses, i, px, py, pz, rx, ry, rz, t);
  }
}

PROBEPROXY_KERNEL void obbBatch(const ObbConstants& box, const RaysSoA& rays,
                                const LookupsSoA& out) {
  PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out);
  const glm::mat3& m = box.unitFromWorld;
  const float m00 = m[0][0], m01 = m[1][0], m02 = m[2][0];
  const float m10 = m[0][1], m11 = m[1][1], m12 = m[2][1];
  const float m20 = m[0][2], m21 = m[1][2], m22 = m[2][2];
  const float cx = box.captureMeters.x, cy = box.captureMeters.y, cz = box.captureMeters.z;
  const float bx = box.centerFromCapture.x, by = box.centerFromCapture.y,
              bz = box.centerFromCapture.z;
  const float ex = 1.0f + box.insideToleranceUnit.x, ey = 1.0f + box.insideToleranceUnit.y,
              ez = 1.0f + box.insideToleranceUnit.z;
#pragma GCC ivdep  // outputs never overlap inputs (batched_lookups.h)
  for (std::size_t i = 0; i < n; ++i) {
    const float px = xs[i] - cx, py = ys[i] - cy, pz = zs[i] - cz;
    const float rx = rxs[i], ry = rys[i], rz = rzs[i];
    const float qx = px - bx, qy = py - by, qz = pz - bz;  // from the box centre
    const float lx = m00 * qx + m01 * qy + m02 * qz;       // unit box space
    const float ly = m10 * qx + m11 * qy + m12 * qz;
    const float lz = m20 * qx + m21 * qy + m22 * qz;
    const float ux = m00 * rx + m01 * ry + m02 * rz;
    const float uy = m10 * rx + m11 * ry + m12 * rz;
    const float uz = m20 * rx + m21 * ry + m22 * rz;
    const float outside =
        std::max(std::max(std::fabs(lx) - ex, std::fabs(ly) - ey), std::fabs(lz) - ez);
    const float tx = slab(-1.0f, 1.0f, lx, ux), ty = slab(-1.0f, 1.0f, ly, uy),
                tz = slab(-1.0f, 1.0f, lz, uz);
    float t = tx < ty ? tx : ty;
    t = t < tz ? t : tz;
    t = t > 0.0f ? t : 0.0f;
    t = outside <= 0.0f ? t : kInf;
    finish(dxs, dys, dzs, misses, i, px, py, pz, rx, ry, rz, t);
  }
}

PROBEPROXY_KERNEL void convexBatch(const ConvexConstants& convex, const RaysSoA& rays,
                                   const LookupsSoA& out) {
  PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS(rays, out);
  const float cx = convex.captureMeters.x, cy = convex.captureMeters.y, cz = convex.captureMeters.z;
  const float tol = 1e-3f;  // kInsideToleranceMeters
  alignas(64) float px[kBlock], py[kBlock], pz[kBlock], tMin[kBlock], outside[kBlock];
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t count = n - begin < kBlock ? n - begin : kBlock;
    const float* __restrict rx = rxs + begin;
    const float* __restrict ry = rys + begin;
    const float* __restrict rz = rzs + begin;
#pragma GCC ivdep  // outputs never overlap inputs (batched_lookups.h)
    for (std::size_t j = 0; j < count; ++j) {
      px[j] = xs[begin + j] - cx, py[j] = ys[begin + j] - cy, pz[j] = zs[begin + j] - cz;
      tMin[j] = kInf;
      outside[j] = -kInf;
    }
    // Planes outer, rays inner: each plane is four broadcast constants and the loop over the
    // block is a straight vector loop.
    for (const glm::vec4& plane : convex.planesFromCapture) {
      const float nx = plane.x, ny = plane.y, nz = plane.z, w = plane.w;
#pragma GCC ivdep  // outputs never overlap inputs (batched_lookups.h)
      for (std::size_t j = 0; j < count; ++j) {
        const float above = nx * px[j] + ny * py[j] + nz * pz[j] - w;  // > 0 outside
        outside[j] = above > outside[j] ? above : outside[j];
        const float towards = nx * rx[j] + ny * ry[j] + nz * rz[j];
        const float toPlane = above < 0.0f ? -above : 0.0f;
        const float tPlane = toPlane / towards;
        const float t = towards > 0.0f ? tPlane : kInf;
        tMin[j] = t < tMin[j] ? t : tMin[j];
      }
    }
#pragma GCC ivdep  // outputs never overlap inputs (batched_lookups.h)
    for (std::size_t j = 0; j < count; ++j)
      finish(dxs, dys, dzs, misses, begin + j, px[j], py[j], pz[j], rx[j], ry[j], rz[j],
             outside[j] <= tol ? tMin[j] : kInf);
  }
}

#undef PROBEPROXY_UNPACK_RAYS_AND_OUTPUTS
#undef PROBEPROXY_KERNEL

}  // namespace probeproxy
