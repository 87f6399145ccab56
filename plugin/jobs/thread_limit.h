#pragma once
// The `threads` option of every job: at most this many TBB worker threads while the job runs
// (0: all cores). Results do not depend on it; only the wall time does.

#include <tbb/global_control.h>

#include <optional>

namespace probeproxy::jobs {

class ThreadLimit {
 public:
  // Throws InputError ("option threads: -1 is negative") for a negative count.
  explicit ThreadLimit(int threads);

 private:
  std::optional<tbb::global_control> control_;
};

}  // namespace probeproxy::jobs
