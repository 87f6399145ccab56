#include "plugin/cost/instructions_per_lookup.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace probeproxy {

namespace {

std::optional<std::filesystem::path> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

std::string commandText(const std::vector<std::string>& args) {
  std::string text;
  for (const std::string& a : args) text += (text.empty() ? "" : " ") + a;
  return text;
}

// Runs args[0] (a path) with the rest as arguments, its stdout and stderr sent to /dev/null;
// returns its exit status (-1 when it did not exit normally).
int runQuietly(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start: " + commandText(args));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("cannot wait for: " + commandText(args));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The total instruction count of a callgrind output file: its "totals:" line (callgrind 3.19
// writes "summary: 0" when collection starts off, so the summary line comes second).
double totalInstructions(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::optional<double> summary;
  while (std::getline(in, line)) {
    if (line.rfind("totals:", 0) == 0) return std::stod(line.substr(7));
    if (line.rfind("summary:", 0) == 0) summary = std::stod(line.substr(8));
  }
  if (summary) return *summary;
  throw std::runtime_error("no instruction total in callgrind output " + file.string());
}

double countInstructions(const std::filesystem::path& valgrind, const std::filesystem::path& driver,
                         const std::string& workload, LookupPath path, std::size_t lookups) {
  static std::atomic<int> counter{0};
  std::string name = "probeproxy-callgrind-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  name += ".out";
  const std::filesystem::path out = std::filesystem::temp_directory_path() / name;
  const std::vector<std::string> args = {valgrind.string(),
                                         "--tool=callgrind",
                                         "--instr-atstart=no",
                                         "--collect-atstart=no",
                                         "--callgrind-out-file=" + out.string(),
                                         driver.string(),
                                         workload,
                                         path == LookupPath::Batched ? "batched" : "scalar",
                                         std::to_string(lookups)};
  const int status = runQuietly(args);
  std::error_code ec;
  if (status != 0) {
    std::filesystem::remove(out, ec);
    std::string problem = "exit status ";
    problem += std::to_string(status);
    problem += ": ";
    problem += commandText(args);
    throw std::runtime_error(problem);
  }
  try {
    const double total = totalInstructions(out);
    std::filesystem::remove(out, ec);
    return total;
  } catch (...) {
    std::filesystem::remove(out, ec);
    throw;
  }
}

}  // namespace

std::filesystem::path lookupCostDriverPath() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = self.parent_path() / "probeproxy_lookup_cost_driver";
    if (std::filesystem::is_regular_file(beside, ec)) return beside;
  }
  return PROBEPROXY_LOOKUP_COST_DRIVER;
}

std::optional<double> instructionsPerLookup(const std::string& workload, LookupPath path,
                                            std::size_t lookups,
                                            const std::filesystem::path& driver) {
  if (lookups == 0) throw std::invalid_argument("instructionsPerLookup: lookups must be positive");
  makeLookupWorkload(workload, 0);  // throws std::invalid_argument on an unknown name
  const std::optional<std::filesystem::path> valgrind = findOnPath("valgrind");
  if (!valgrind) return std::nullopt;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(driver, ec)) {
    throw std::runtime_error("lookup cost driver is missing: " + driver.string());
  }
  const double once = countInstructions(*valgrind, driver, workload, path, lookups);
  const double twice = countInstructions(*valgrind, driver, workload, path, 2 * lookups);
  return (twice - once) / static_cast<double>(lookups);
}

}  // namespace probeproxy
