#pragma once
// `demo`: the main job, end to end, on the built-in level (the seed's corridor), so a new user
// sees what the tool does with nothing but the binary: the level written and read back, depth
// cubes checked against the exact corridor, proxies built and exported, the volumes validated,
// the blend weights drawn, and every method benchmarked and charted.

#include <filesystem>
#include <iosfwd>

namespace probeproxy::jobs {

struct DemoJobOptions {
  std::filesystem::path outFolder = "probeproxy-demo";
  int faceSize = 128;  // depth cube face, texels
  bool bench = true;   // the speed-against-accuracy benchmark and its charts

  void check() const;  // throws InputError: no folder, face_size outside [8, 2048]
};

// Says what it does, stage by stage, on `narrative` (the demo's result is that account and
// the files it names).
void runDemoJob(const DemoJobOptions& options, std::ostream& narrative);

}  // namespace probeproxy::jobs
