#include "plugin/jobs/layout/candidate_judge.h"

#include "plugin/jobs/thread_limit.h"

namespace probeproxy::jobs {

CandidateJudge::CandidateJudge(const LayoutJobOptions& o)
    : threads_(o.threads), setup_((o.check(), prepareLayout(o))) {
  const ThreadLimit threads(threads_);
  floor_ = walkableFloor(*setup_.rayCaster, setup_.seedsMeters, setup_.layout.floor);
  ground_ = candidateGround(*setup_.rayCaster, floor_, setup_.layout);
}

std::string CandidateJudge::judge(std::span<const std::size_t> captures) const {
  const ThreadLimit threads(threads_);
  return judgeCandidates(*setup_.rayCaster, ground_, captures);
}

}  // namespace probeproxy::jobs
