#pragma once
// One process's share of a layout's work, for a layout spread over processes or machines: made
// once per process from the layout job's options (the level read, its floor walked, the floor
// samples and capture points laid as the job lays them: layout_setup.h, run_layout.h's
// candidateGround), then asked for the candidates of any capture points, packed for the process
// that selects (candidate_wire.h), and for the final proxy of any probe it lays out, packed too
// (proxy_build_wire.h). A Dask worker keeps one per level and options (scripts/layout_dask.py),
// so the level is read once per worker, and what travels is served floor and proxies, not
// meshes.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"
#include "plugin/jobs/layout/layout_job.h"
#include "plugin/jobs/layout/layout_setup.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace probeproxy::jobs {

class LayoutWorker {
 public:
  // Throws InputError as runLayoutJob does for the same options.
  explicit LayoutWorker(const LayoutJobOptions& options);

  std::size_t capturePoints() const { return ground_.captures.points.size(); }
  // judgeCandidates of these capture points (indices as the job's layout numbers them).
  std::string judge(std::span<const std::size_t> captures) const;
  // The packed buildLayoutProxy of a packed task (LayoutJobOptions::buildProxies), with the
  // job's final proxy options and tolerance. Throws InputError for bytes that are not a task.
  std::string buildProxy(std::string_view task) const;

 private:
  int threads_;
  LayoutSetup setup_;
  WalkableFloor floor_;
  CandidateGround ground_;
};

}  // namespace probeproxy::jobs
