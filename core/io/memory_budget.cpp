#include "core/io/memory_budget.h"

#include "core/errors/input_error.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace probeproxy {

std::uint64_t usableMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageBytes = sysconf(_SC_PAGE_SIZE);
  std::uint64_t usable =
      pages > 0 && pageBytes > 0 ? std::uint64_t(pages) * std::uint64_t(pageBytes) : UINT64_MAX;
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit limit{};
    if (getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      usable = std::min<std::uint64_t>(usable, limit.rlim_cur);
  }
  return usable;
}

void requireMemory(const std::string& what, std::uint64_t neededBytes, std::uint64_t budgetBytes,
                   const std::string& needs, const std::string& advice) {
  const bool given = budgetBytes > 0;
  const std::uint64_t budget = given ? budgetBytes : usableMemoryBytes();
  if (neededBytes <= budget) return;
  throw InputError(what, needs + " may take " + gibibytesText(neededBytes) + ", more than the " +
                             gibibytesText(budget) +
                             (given ? " of --max-memory" : " this process can use") + "; " +
                             advice + " or raise --max-memory");
}

std::string gibibytesText(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
  return text;
}

}  // namespace probeproxy
