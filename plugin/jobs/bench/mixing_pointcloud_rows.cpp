#include "plugin/jobs/bench/mixing_pointcloud_rows.h"

#include "core/mixing/reflected_camera.h"
#include "geometry/evaluation/evaluate_mixing.h"
#include "geometry/mirror_view/radiance_lookups.h"
#include "geometry/pointcloud/probe_point_cloud.h"

#include <cmath>
#include <stdexcept>

namespace probeproxy::jobs {

namespace {

// The mixing step draws planes and triangles: boxes and convex proxies with a boundary mesh.
std::optional<ConvexProxy> mixingVolume(const ProxyShape& shape) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) return convexFromBox(*box);
  if (const auto* convex = std::get_if<ConvexProxy>(&shape);
      convex != nullptr && !convex->planes.empty() && !convex->triangles.empty())
    return *convex;
  return std::nullopt;
}

double texelCount(const Cubemap& cube) {
  double texels = 0.0;
  for (int level = 0; level < cube.numLevels(); ++level)
    texels += kCubeFaceCount * double(cube.faceSize(level)) * double(cube.faceSize(level));
  return texels;
}

BenchResult rowOf(const ProbeBenchInputs& in, std::string method, std::string candidate) {
  BenchResult row;
  row.scene = in.scene;
  row.probe = in.probe->name;
  row.method = std::move(method);
  row.candidate = std::move(candidate);
  return row;
}

}  // namespace

std::vector<MethodRow> mixingRows(const ProbeBenchInputs& in) {
  const std::optional<ConvexProxy> volume = mixingVolume(in.kept->shape);
  if (!volume || in.probe->reflectionPlanes.empty()) return {};
  const ReflectionPlane plane = in.probe->reflectionPlanes.front();
  const glm::dvec3 c = in.probe->captureMeters;
  const int faceSize = in.images ? in.images->cube.faceSize(0) : in.faceSize;
  std::vector<MethodRow> rows;
  for (MixingMethod method : {MixingMethod::MixingPlane, MixingMethod::RasterConvex}) {
    MethodRow m{rowOf(in, std::string(mixingMethodName(method)), candidateName(*in.kept)),
                std::nullopt};
    m.row.planes = static_cast<int>(volume->planes.size());
    m.row.kept = true;
    try {
      m.row.error = evaluateMixing(method, *volume, c, plane, in.mirrorFloor, faceSize);
      if (in.images) {
        m.row.psnrDb = meanPsnrDb(in.images->views, [&](const MirrorViewReference& view) {
          const glm::dvec3 reflected =
              reflectThroughPlane(view.view.positionMeters, view.view.mirrorPlane);
          // Owned by the lookup: the reconstruction calls it after this lambda returns.
          auto corrected = std::make_shared<CorrectedCubemap>(
              correctCubemap(in.images->cube, c, *volume, reflected, method));
          return RadianceLookup([corrected, lookup = correctedCubeRadianceLookup(*corrected)](
                                    glm::dvec3 x, glm::dvec3 r) { return lookup(x, r); });
        });
        const glm::dvec3 reflected =
            reflectThroughPlane(in.images->views.front().view.positionMeters,
                                in.images->views.front().view.mirrorPlane);
        m.cost = CallJob{[images = in.images, c, proxy = *volume, reflected, method] {
                           const CorrectedCubemap corrected =
                               correctCubemap(images->cube, c, proxy, reflected, method);
                           keepResult(corrected.cube.levels.front().rgb[0].data());
                         },
                         texelCount(in.images->cube)};
      }
    } catch (const std::invalid_argument&) {
      continue;  // a proxy the step cannot run on: no row rather than made-up figures
    }
    rows.push_back(std::move(m));
  }
  return rows;
}

std::vector<MethodRow> pointCloudRows(const ProbeBenchInputs& in) {
  if (!in.images) return {};
  auto cloud = std::make_shared<PointCloud>(
      probePointCloud(*in.level, in.images->cube, in.probe->captureMeters));
  MethodRow m{rowOf(in, "pointcloud", "pointcloud"), std::nullopt};
  // No lookup direction: no angular error, and no miss rate on mirror_floor either.
  m.row.error.missRate = std::nan("");
  m.row.error.occludedRate = std::nan("");
  const PointCloudOptions options;
  std::vector<MirrorViewReference> sparse = in.images->views;
  for (MirrorViewReference& view : sparse) {
    std::size_t seen = 0;
    for (std::uint8_t& inMask : view.mask) inMask = inMask && seen++ % 8 == 0;
  }
  m.row.psnrDb = meanPsnrDb(sparse, [&](const MirrorViewReference&) {
    return pointCloudRadianceLookup(*cloud, options);
  });
  // The first shading points of the mirror_floor draw, one splat each.
  std::vector<ReflectionSample> points(
      in.mirrorFloor.begin(),
      in.mirrorFloor.begin() + std::min<std::size_t>(8, in.mirrorFloor.size()));
  if (!points.empty()) {
    const double count = static_cast<double>(points.size());
    m.cost = CallJob{[cloud, points = std::move(points), options] {
                       for (const ReflectionSample& s : points) {
                         const std::optional<glm::vec3> rgb =
                             pointCloudRadiance(*cloud, s.xMeters, glm::vec3(s.reflected), options);
                         keepResult(&rgb);
                       }
                     },
                     count};
  }
  return {std::move(m)};
}

}  // namespace probeproxy::jobs
