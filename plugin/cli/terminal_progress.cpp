#include "plugin/cli/terminal_progress.h"

#include <unistd.h>
#include <iostream>

namespace probeproxy::cli {

jobs::Progress terminalProgress(std::string what, std::string items) {
  if (::isatty(STDERR_FILENO) == 0) return {};
  return [what = std::move(what), items = std::move(items)](std::size_t done, std::size_t total) {
    std::cerr << "\r" << what << ": " << done << "/" << total << " " << items << std::flush;
    if (done == total) std::cerr << "\n";
  };
}

}  // namespace probeproxy::cli
