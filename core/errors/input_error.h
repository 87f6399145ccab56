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

// Control characters (a newline in a path, an escape in a file name) written as \n, \t, \xNN,
// so that a message stays one line on a terminal and in a log.
inline std::string oneLine(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string line;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (c == '\t') {
      line += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      line += "\\x";
      line += kHex[byte >> 4];
      line += kHex[byte & 15];
    } else {
      line += c;
    }
  }
  return line;
}

class InputError : public std::runtime_error {
 public:
  InputError(const std::filesystem::path& file, const std::string& problem)
      : std::runtime_error(oneLine(file.string() + ": " + problem)), file_(file),
        problem_(problem) {}

  const std::filesystem::path& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::filesystem::path file_;
  std::string problem_;
};

}  // namespace probeproxy
