#include "plugin/jobs/layout/layout_worker.h"

#include "geometry/layout/layout_proxy.h"
#include "geometry/layout/proxy_build_wire.h"
#include "plugin/jobs/thread_limit.h"

namespace probeproxy::jobs {

LayoutWorker::LayoutWorker(const LayoutJobOptions& o)
    : threads_(o.threads), setup_((o.check(), prepareLayout(o))) {
  const ThreadLimit threads(threads_);
  floor_ = walkableFloor(*setup_.rayCaster, setup_.seedsMeters, setup_.layout.floor);
  ground_ = candidateGround(*setup_.rayCaster, floor_, setup_.layout);
}

std::string LayoutWorker::judge(std::span<const std::size_t> captures) const {
  const ThreadLimit threads(threads_);
  return judgeCandidates(*setup_.rayCaster, ground_, captures);
}

std::string LayoutWorker::buildProxy(std::string_view task) const {
  const ProxyBuildTask t = unpackProxyBuildTask(task);
  const ThreadLimit threads(threads_);
  return packProxyBuild(buildLayoutProxy(*setup_.rayCaster, t.probe, setup_.layout.finalProxy,
                                         t.candidateFitMeters, setup_.layout.toleranceDeg,
                                         {t.blendVolumes, t.blendIndex}));
}

}  // namespace probeproxy::jobs
