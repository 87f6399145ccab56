// The mixing-step correction (Lagarde & Zanuttini 2012): reflected camera, per-texel and rasterized
// lookup cubes against each other at every mip size, against the exact answer of a box room with a
// mirror floor, and on degenerate set-ups (E' on the proxy boundary, rays parallel to faces).

#include "core/mixing/corrected_cubemap.h"
#include "core/mixing/mixing_plane.h"
#include "core/mixing/raster_convex.h"
#include "core/mixing/reflected_camera.h"
#include "core/parallax/reference_lookup.h"
#include "core/raster/face_rasterizer.h"
#include "tests/unit/mixing_agreement.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace probeproxy {
namespace {

using test::angleRadians;
using test::expectMixingMethodsAgree;

// The analytic room: a 6 x 4 x 3 m box, floor at z = 0 (the mirror), probe off centre.
const BoxShape kRoom{{0.0, 0.0, 1.5}, {3.0, 2.0, 1.5}, {1, 0, 0, 0}};
const glm::dvec3 kCapture{0.5, 0.3, 1.4};
const glm::dvec3 kCamera{1.1, -0.7, 1.7};
const ReflectionPlane kFloor{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};

TEST(ReflectedCamera, MirrorsThroughAnyPlane) {
  EXPECT_EQ(reflectThroughPlane(kCamera, kFloor), glm::dvec3(1.1, -0.7, -1.7));
  // A tilted plane given with a non-unit normal: E' - E is along the normal, the midpoint on it.
  const ReflectionPlane tilted{{1.0, 2.0, 3.0}, {0.0, 3.0, 4.0}};
  const glm::dvec3 e(2.0, -1.0, 5.0);
  const glm::dvec3 mirrored = reflectThroughPlane(e, tilted);
  EXPECT_NEAR(heightAbovePlaneMeters(0.5 * (e + mirrored), tilted), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(glm::cross(mirrored - e, tilted.normal)), 0.0, 1e-12);
  EXPECT_NEAR(heightAbovePlaneMeters(mirrored, tilted), -heightAbovePlaneMeters(e, tilted), 1e-12);
  EXPECT_THROW(reflectThroughPlane(e, {{0, 0, 0}, {0, 0, 0}}), std::invalid_argument);
}

TEST(ReflectedCamera, OutsideTheRoomIsReportedAndEnlargingBelowTheFloorFixesIt) {
  // The seed's glossy rule: E' = (1.1, -0.7, -1.7) lies 1.7 m below the room's floor.
  const ReflectedCameraCheck room =
      reflectedCameraInsideProxy(kCamera, kFloor, convexFromBox(kRoom));
  EXPECT_FALSE(room.inside);
  EXPECT_NEAR(room.outsideByMeters, 1.7, 1e-12);
  // The room's proxy enlarged 2 m below the floor ("enlarge geometry proxy") contains it.
  BoxShape enlarged = kRoom;
  enlarged.centerMeters.z -= 1.0;
  enlarged.halfExtentsMeters.z += 1.0;
  const ReflectedCameraCheck fixed =
      reflectedCameraInsideProxy(kCamera, kFloor, convexFromBox(enlarged));
  EXPECT_TRUE(fixed.inside);
  EXPECT_NEAR(fixed.outsideByMeters, -0.3, 1e-12);
  // Then no direction of the corrected cube misses, even into the lower hemisphere.
  const LookupCube lookups =
      mixingPlaneLookups(convexFromBox(enlarged), kCapture, fixed.reflectedCameraMeters, 16);
  for (const auto& face : lookups.miss)
    for (std::uint8_t m : face) EXPECT_EQ(m, 0);
}

// Every mip size of a 64 px chain, E' below the floor (outside), inside an enlarged proxy, and
// exactly on the enlarged proxy's bottom face.
TEST(MixingStep, PerTexelAndRasterizedAgreeOnABoxAtEveryMipSize) {
  const glm::dvec3 reflected = reflectThroughPlane(kCamera, kFloor);
  BoxShape enlarged = kRoom;
  enlarged.centerMeters.z -= 1.5;
  enlarged.halfExtentsMeters.z += 1.5;  // bottom at z = -1.5: E' inside
  BoxShape touching = kRoom;
  touching.centerMeters.z -= 0.85;
  touching.halfExtentsMeters.z += 0.85;  // bottom at z = -1.7: E' on it
  for (const BoxShape& box : {kRoom, enlarged, touching}) {
    for (int n = 64; n >= 1; n /= 2) {
      SCOPED_TRACE("box bottom " + std::to_string(box.centerMeters.z - box.halfExtentsMeters.z) +
                   ", face size " + std::to_string(n));
      const test::AgreementFigures figures =
          expectMixingMethodsAgree(convexFromBox(box), kCapture, reflected, n);
      EXPECT_GT(figures.bothHit, 0);
      // Away from the boundary only silhouette texels can graze.
      if (box.centerMeters.z != touching.centerMeters.z) {
        EXPECT_LE(figures.grazingMismatches, 4 * n);
      }
    }
  }
}

// Odd face sizes put a texel centre exactly on each face's axes, so rays run exactly parallel
// to four box planes; with E' on the bottom plane, the middle rows run inside that plane.
TEST(MixingStep, RaysParallelToFacesAndEyeOnTheBoundaryStayFinite) {
  BoxShape touching = kRoom;
  touching.centerMeters.z -= 0.85;
  touching.halfExtentsMeters.z += 0.85;
  const glm::dvec3 reflected = reflectThroughPlane(kCamera, kFloor);
  for (int n : {1, 3, 33}) {
    SCOPED_TRACE("face size " + std::to_string(n));
    const test::AgreementFigures figures =
        expectMixingMethodsAgree(convexFromBox(touching), kCapture, reflected, n);
    EXPECT_GT(figures.bothHit, 0);
  }
  // Rays straight down from E' on the bottom face leave at once: a miss, not P = E'.
  const LookupCube lookups = mixingPlaneLookups(convexFromBox(touching), kCapture, reflected, 3);
  EXPECT_EQ(lookups.miss[static_cast<int>(CubeFace::nz)][4], 1);
  EXPECT_EQ(lookups.miss[static_cast<int>(CubeFace::pz)][4], 0);
  // A ray in a plane of the proxy, parallel to it, from outside: no chord, no NaN.
  const RayChord parallel =
      rayChord(convexFromBox(kRoom).planes, {0.0, 0.0, -1.0}, {1.0, 0.0, 0.0});
  EXPECT_FALSE(rayExitsProxy(parallel));
}

TEST(MixingStep, FarFromTheOriginBothMethodsStillAgree) {
  const glm::dvec3 offset(1e5, -1e5, 1e5);
  BoxShape far = kRoom;
  far.centerMeters += offset;
  const ReflectionPlane floor{offset, {0, 0, 1}};
  const glm::dvec3 reflected = reflectThroughPlane(kCamera + offset, floor);
  const test::AgreementFigures figures =
      expectMixingMethodsAgree(convexFromBox(far), kCapture + offset, reflected, 32);
  EXPECT_GT(figures.bothHit, 0);
}

// A source cubemap whose texels hold the world point their direction hits in the room (exact
// box distances): the corrected cube from E' must then hold, texel by texel, the point the
// mirror floor really shows along the reflected ray, which the per-pixel reference lookup
// computes independently from the floor point x and the camera's reflected view ray.
Cubemap roomPositionCube(int n) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const glm::dvec3 d =
            glm::normalize(texelRayDirection(static_cast<CubeFace>(f), col, row, n));
        const glm::dvec3 hit = *referenceLookup(kRoom, kCapture, kCapture, d) + kCapture;
        for (int c = 0; c < 3; ++c) faces[f].push_back(static_cast<float>(hit[c]));
      }
    }
  }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  return cube;
}

TEST(MixingStep, BoxRoomMirrorFloorMatchesTheExactReflection) {
  const int n = 64;
  const Cubemap source = roomPositionCube(n);
  const glm::dvec3 reflected = reflectThroughPlane(kCamera, kFloor);
  const ConvexProxy proxy = convexFromBox(kRoom);
  for (MixingMethod method : {MixingMethod::MixingPlane, MixingMethod::RasterConvex}) {
    SCOPED_TRACE(std::string(mixingMethodName(method)));
    const CorrectedCubemap corrected = correctCubemap(source, kCapture, proxy, reflected, method);
    ASSERT_EQ(corrected.cube.numLevels(), source.numLevels());
    for (int level = 0; level < source.numLevels(); ++level) {
      const int size = source.faceSize(level);
      // A texel of this level spans at most 2 atan(1/size) seen from C; bilinear filtering of
      // exact wall points lands within a texel of the true direction (mips: within one of theirs).
      const double texelRadians = 2.0 * std::atan(1.0 / size);
      const LookupCube lookups = mixingLookups(method, proxy, kCapture, reflected, size);
      int checked = 0;
      for (int f = 0; f < kCubeFaceCount; ++f) {
        for (int row = 0; row < size; ++row) {
          for (int col = 0; col < size; ++col) {
            const glm::dvec3 d = texelRayDirection(static_cast<CubeFace>(f), col, row, size);
            const std::size_t i = static_cast<std::size_t>(row) * size + col;
            // The floor point x that the camera sees along this reflected ray.
            if (!(d.z > 0)) continue;
            const glm::dvec3 x = reflected + (-reflected.z / d.z) * d;
            // Only where the floor is (elsewhere the camera sees no mirror), and not grazing its
            // edge, where either answer is right.
            if (std::abs(x.x - kRoom.centerMeters.x) >= 3.0 - 1e-9 ||
                std::abs(x.y - kRoom.centerMeters.y) >= 2.0 - 1e-9)
              continue;
            ASSERT_EQ(corrected.missMask[level][f][i], 0)
                << "level " << level << " face " << f << " (" << col << ", " << row << ") x " << x.x
                << " " << x.y;
            const glm::dvec3 exact = *referenceLookup(kRoom, kCapture, x, d);
            EXPECT_LT(glm::length(lookups.lookupMeters[f][i] - exact), 1e-9);
            const float* rgb = &corrected.cube.levels[level].rgb[f][i * 3];
            const glm::dvec3 shown(rgb[0], rgb[1], rgb[2]);
            EXPECT_LE(angleRadians(shown - kCapture, exact), texelRadians)
                << "level " << level << " face " << f << " (" << col << ", " << row << ")";
            ++checked;
          }
        }
      }
      EXPECT_GT(checked, 0);
    }
  }
}

TEST(MixingStep, MissedTexelsAreRedAndFlaggedNeverNaN) {
  const Cubemap source = roomPositionCube(8);
  const CorrectedCubemap corrected =
      correctCubemap(source, kCapture, convexFromBox(kRoom), reflectThroughPlane(kCamera, kFloor),
                     MixingMethod::MixingPlane);
  EXPECT_GT(missCount(corrected), 0u);
  for (std::size_t l = 0; l < corrected.missMask.size(); ++l) {
    for (int f = 0; f < kCubeFaceCount; ++f) {
      const auto& rgb = corrected.cube.levels[l].rgb[f];
      for (std::size_t i = 0; i < corrected.missMask[l][f].size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(rgb[i * 3 + c]));
        if (corrected.missMask[l][f][i]) {
          EXPECT_EQ(glm::vec3(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2]), glm::vec3(1, 0, 0));
        }
      }
    }
  }
  // Straight down from below the floor every ray misses the room.
  EXPECT_EQ(corrected.missMask[0][static_cast<int>(CubeFace::nz)],
            std::vector<std::uint8_t>(64, 1));
}

TEST(FaceRasterizer, TwoTrianglesOfAQuadCoverEveryTexelOnce) {
  // A quad straddling the face centre whose diagonal runs through texel centres: every texel is
  // covered by exactly one of the two triangles (top-left rule), none twice, none dropped.
  const int n = 8;
  const glm::dvec3 a(1, 1, 0.5), b(1, -1, 0.5), c(1, -1, -0.5), d(1, 1, -0.5);  // px face
  FaceTarget first = emptyFaceTarget(n), second = emptyFaceTarget(n), both = emptyFaceTarget(n);
  const std::array<RasterVertex, 3> t0{RasterVertex{a, {1, 0, 0}}, RasterVertex{b, {1, 0, 0}},
                                       RasterVertex{c, {1, 0, 0}}};
  const std::array<RasterVertex, 3> t1{RasterVertex{a, {0, 1, 0}}, RasterVertex{c, {0, 1, 0}},
                                       RasterVertex{d, {0, 1, 0}}};
  rasterizeTriangle(CubeFace::px, {0, 0, 0}, 1e-6, t0, first);
  rasterizeTriangle(CubeFace::px, {0, 0, 0}, 1e-6, t1, second);
  for (std::size_t i = 0; i < first.covered.size(); ++i) {
    const int row = static_cast<int>(i) / n;
    const bool inQuad = row >= 2 && row < 6;  // z in [-0.5, 0.5] is rows 2..5
    EXPECT_EQ(first.covered[i] + second.covered[i], inQuad ? 1 : 0) << "texel " << i;
  }
  // Perspective-correct: a tilted triangle's interpolated attribute (its world point) lies on
  // the ray through the texel centre.
  const glm::dvec3 p0(1, 2, 1), p1(3, -2, 1), p2(2, 0, -3);
  rasterizeTriangle(CubeFace::px, {0, 0, 0}, 1e-6,
                    {RasterVertex{p0, p0}, RasterVertex{p1, p1}, RasterVertex{p2, p2}}, both);
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n; ++col)
      if (both.covered[row * n + col]) {
        EXPECT_LT(angleRadians(both.attribute[row * n + col],
                               texelRayDirection(CubeFace::px, col, row, n)),
                  1e-12);
      }
}

}  // namespace
}  // namespace probeproxy
