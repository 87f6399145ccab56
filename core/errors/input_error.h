#pragma once
// Bad input that the user can fix: a missing or unreadable file, a malformed mesh, a NaN
// coordinate, a wrong scene field. The library never exits the process (the add-on runs it
// inside Blender); it throws this, and each front end turns it into one line: the CLI prints
// what() and exits with kExitBadInput, the Python module raises it as an exception.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace probeproxy {

inline constexpr int kExitBadInput = 2;

class InputError : public std::runtime_error {
 public:
  InputError(const std::filesystem::path& file, const std::string& problem)
      : std::runtime_error(file.string() + ": " + problem), file_(file), problem_(problem) {}

  const std::filesystem::path& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::filesystem::path file_;
  std::string problem_;
};

}  // namespace probeproxy
