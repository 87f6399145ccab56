#include "plugin/jobs/thread_limit.h"

#include "core/errors/option_checks.h"

namespace probeproxy::jobs {

ThreadLimit::ThreadLimit(int threads) {
  requireInRange("threads", threads, 0, 4096);
  if (threads > 0) control_.emplace(tbb::global_control::max_allowed_parallelism, threads);
}

}  // namespace probeproxy::jobs
