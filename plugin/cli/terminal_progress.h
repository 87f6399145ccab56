#pragma once
// Progress of a long job on a terminal: "\r<what>: done/total <items>" on stderr, a newline
// when done. Nothing when stderr is not a terminal, so logs and CI output stay clean.

#include "plugin/jobs/job_progress.h"

#include <string>

namespace probeproxy::cli {

jobs::Progress terminalProgress(std::string what, std::string items);

}  // namespace probeproxy::cli
