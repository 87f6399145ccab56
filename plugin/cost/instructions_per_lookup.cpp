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

// A fresh callgrind output file name in the temporary folder.
std::filesystem::path callgrindOutFile() {
  static std::atomic<int> counter{0};
  std::string name = "probeproxy-callgrind-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  name += ".out";
  return std::filesystem::temp_directory_path() / name;
}

// Runs the driver with `driverArgs` under callgrind writing to `out` (and, for a dumping run,
// `out`.1, `out`.2, ...); reads the totals of the files `read` names; removes every file.
std::vector<double> callgrindTotals(const std::filesystem::path& valgrind,
                                    const std::filesystem::path& driver,
                                    const std::vector<std::string>& driverArgs,
                                    const std::filesystem::path& out,
                                    const std::vector<std::filesystem::path>& read) {
  std::vector<std::string> args = {valgrind.string(),
                                   "--tool=callgrind",
                                   "--instr-atstart=no",
                                   "--collect-atstart=no",
                                   "--callgrind-out-file=" + out.string(),
                                   driver.string()};
  args.insert(args.end(), driverArgs.begin(), driverArgs.end());
  const int status = runQuietly(args);
  const auto removeAll = [&] {
    std::error_code ec;
    std::filesystem::remove(out, ec);
    for (const std::filesystem::path& file : read) std::filesystem::remove(file, ec);
  };
  if (status != 0) {
    removeAll();
    std::string problem = "exit status ";
    problem += std::to_string(status);
    problem += ": ";
    problem += commandText(args);
    throw std::runtime_error(problem);
  }
  try {
    std::vector<double> totals;
    for (const std::filesystem::path& file : read) totals.push_back(totalInstructions(file));
    removeAll();
    return totals;
  } catch (...) {
    removeAll();
    throw;
  }
}

std::string pathName(LookupPath path) { return path == LookupPath::Batched ? "batched" : "scalar"; }

double countInstructions(const std::filesystem::path& valgrind, const std::filesystem::path& driver,
                         const std::string& workload, LookupPath path, std::size_t lookups) {
  const std::filesystem::path out = callgrindOutFile();
  return callgrindTotals(valgrind, driver, {workload, pathName(path), std::to_string(lookups)}, out,
                         {out})
      .front();
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

std::vector<std::optional<double>> instructionsPerLookup(const std::vector<std::string>& workloads,
                                                         LookupPath path, std::size_t lookups,
                                                         const std::filesystem::path& driver) {
  if (lookups == 0) throw std::invalid_argument("instructionsPerLookup: lookups must be positive");
  for (const std::string& w : workloads) makeLookupWorkload(w, 0);  // unknown names throw
  const std::optional<std::filesystem::path> valgrind = findOnPath("valgrind");
  if (!valgrind || workloads.empty()) return std::vector<std::optional<double>>(workloads.size());
  std::error_code ec;
  if (!std::filesystem::is_regular_file(driver, ec)) {
    throw std::runtime_error("lookup cost driver is missing: " + driver.string());
  }
  const std::filesystem::path out = callgrindOutFile();
  std::vector<std::string> args = {"--dumps", pathName(path), std::to_string(lookups)};
  args.insert(args.end(), workloads.begin(), workloads.end());
  std::vector<std::filesystem::path> dumps;
  for (std::size_t i = 1; i <= 2 * workloads.size(); ++i)
    dumps.push_back(out.string() + "." + std::to_string(i));
  const std::vector<double> totals = callgrindTotals(*valgrind, driver, args, out, dumps);
  std::vector<std::optional<double>> perLookup;
  for (std::size_t i = 0; i < workloads.size(); ++i)
    perLookup.push_back((totals[2 * i + 1] - totals[2 * i]) / static_cast<double>(lookups));
  return perLookup;
}

}  // namespace probeproxy
