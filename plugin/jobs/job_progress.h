#pragma once
// How a long job tells its front end how far it got. The CLI draws it on a terminal, the
// Python module hands it to Blender's progress bar on the main thread; a job never prints.

#include <cstddef>
#include <exception>
#include <functional>
#include <string_view>

namespace probeproxy::jobs {

// `(done, total)` as items finish (probes built, benchmarks timed). May be called from worker
// threads, one call at a time.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

// Thrown by a front end's Progress to stop a job (the artist pressed Esc): the job unwinds from
// the next report, writing nothing it had not finished writing.
struct JobCancelled : std::exception {
  const char* what() const noexcept override { return "cancelled"; }
};

// One line of narrative: a stage that finished, a file that was written.
using Say = std::function<void(std::string_view line)>;

}  // namespace probeproxy::jobs
