// The command line over a small level: every verb, with arguments from the input, as a user
// or a script types them (plugin/cli/command_line.h). The readers' targets never reach an
// option's value or what a level's numbers do past the reader (a blend band of 1e20 m, a capture
// point outside the room, a floor too big for memory); this one does.
//
// The input is the argument list, one argument a line. SCENE stands for a scene this target
// writes once (a 6 x 4 x 3 m room with a pillar, one probe with an 8-texel cubemap), LEVEL for
// its level mesh, and OUT for a folder emptied before every run. A run may end in exit 0, 1 or 2;
// exit 3 (an internal error), a crash, a hang or an allocation past the limit is a finding.
#include "core/cube/cubemap.h"
#include "core/cube/cubemap_io.h"
#include "fuzz_input.h"
#include "plugin/cli/command_line.h"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace probeproxy;

// Walls facing into the room, a pillar's faces facing out; corners listed counter-clockwise
// seen from the side each face is lit from.
const char kRoomOff[] =
    "OFF\n16 12 0\n"
    "0 0 0\n6 0 0\n6 4 0\n0 4 0\n0 0 3\n6 0 3\n6 4 3\n0 4 3\n"
    "2.8 1.8 0\n3.2 1.8 0\n3.2 2.2 0\n2.8 2.2 0\n2.8 1.8 3\n3.2 1.8 3\n3.2 2.2 3\n2.8 2.2 3\n"
    "4 0 1 2 3\n4 4 7 6 5\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n"
    "4 8 9 13 12\n4 9 10 14 13\n4 10 11 15 14\n4 11 8 12 15\n4 8 11 10 9\n4 12 13 14 15\n";

const char kScene[] = R"({"probeproxy_scene": 1, "up": "Z", "level": ["room.off"],
 "probes": [{"name": "p", "capture": [1.5, 1.5, 1.6],
  "influence": {"kind": "box", "center": [3, 2, 1.5], "half_extents": [3, 2, 1.5]},
  "proxy": "auto", "cubemap": "cube_{face}.exr",
  "reflection_planes": [{"point": [0, 0, 0], "normal": [0, 0, 1]}]}]})";

struct Level {
  fs::path scene, level, out, workingFolder;
};

const Level& level() {
  static const Level files = [] {
    Level l;
    l.level = fuzz::writeScratch("room.off", kRoomOff);
    l.scene = fuzz::writeScratch("room.scene.json", kScene);
    l.out = fuzz::scratchFile("out");
    // A mutated argument is often a relative path: an --out of "O\tUT" must land in the
    // scratch, not in the folder the campaign was started from.
    l.workingFolder = fuzz::scratchFile("cwd");
    std::array<std::vector<float>, kCubeFaceCount> faces;
    for (std::vector<float>& face : faces) face.assign(8 * 8 * 3, 0.5f);
    writeCubemap(Cubemap::fromFaces(8, faces), fuzz::scratchFile("cube_{face}.exr").string(), 0);
    return l;
  }();
  return files;
}

std::string substituted(std::string argument, const Level& l) {
  for (const auto& [token, path] :
       {std::pair{"SCENE", l.scene.string()}, std::pair{"LEVEL", l.level.string()},
        std::pair{"OUT", l.out.string()}}) {
    for (std::size_t at; (at = argument.find(token)) != std::string::npos;)
      argument.replace(at, std::string_view(token).size(), path);
  }
  return argument;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Level& l = level();
  std::vector<std::string> arguments{"probeproxy"};
  std::istringstream lines{std::string(fuzz::asText(data, size))};
  for (std::string line; std::getline(lines, line) && arguments.size() < 64;)
    arguments.push_back(substituted(line, l));
  // A demo writes a level's worth of pictures and a bench times for minutes: neither reads an
  // option value the other verbs do not.
  if (arguments.size() < 2 || arguments[1] == "demo" || arguments[1] == "bench") return -1;
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::error_code ignored;
  fs::remove_all(l.out, ignored);
  fs::remove_all(l.workingFolder, ignored);
  fs::create_directories(l.workingFolder);
  fs::current_path(l.workingFolder);
  std::ostringstream out, err;
  std::streambuf* const stdoutWas = std::cout.rdbuf(out.rdbuf());
  std::streambuf* const stderrWas = std::cerr.rdbuf(err.rdbuf());
  const int code = cli::runCommandLine(int(arguments.size()), argv.data());
  std::cout.rdbuf(stdoutWas);
  std::cerr.rdbuf(stderrWas);
  if (code == cli::kExitInternalError) {
    std::cerr << "exit 3:";
    for (const std::string& a : arguments) std::cerr << " '" << a << "'";
    std::cerr << "\n" << err.str();
    std::abort();
  }
  return 0;
}
