#pragma once
// One process's share of a layout's candidate stage: made once per process from the layout
// job's options (the level read, its floor walked, the floor samples and capture points laid
// as the job lays them: layout_setup.h, run_layout.h's candidateGround), then asked for the
// candidates of any capture points, packed for the process that selects (candidate_wire.h).
// A Dask worker keeps one per level and options (scripts/layout_dask.py), so the level is read
// once per worker, and what travels back is served floor, not meshes.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/run_layout.h"
#include "plugin/jobs/layout/layout_job.h"
#include "plugin/jobs/layout/layout_setup.h"

#include <cstddef>
#include <span>
#include <string>

namespace probeproxy::jobs {

class CandidateJudge {
 public:
  // Throws InputError as runLayoutJob does for the same options.
  explicit CandidateJudge(const LayoutJobOptions& options);

  std::size_t capturePoints() const { return ground_.captures.points.size(); }
  // judgeCandidates of these capture points (indices as the job's layout numbers them).
  std::string judge(std::span<const std::size_t> captures) const;

 private:
  int threads_;
  LayoutSetup setup_;
  WalkableFloor floor_;
  CandidateGround ground_;
};

}  // namespace probeproxy::jobs
