#pragma once
// `build` and `export`: every probe's proxy built from the level, every candidate measured,
// the kept ones exported for the runtime (proxies.json + proxies.glb).
//
// Path of one run: plugin/cli/verbs/build_verb.cpp parses flags into BuildJobOptions ->
// runBuildJob (here) reads the scene and level -> geometry/probe_proxies/build_scene_proxies.h
// builds each probe (geometry/probe_proxies/build_probe_proxy.h: depth cube, samples, fits,
// simplification, evaluation, selection) -> core/parallax measures each lookup -> geometry/export
// writes the files.

#include "core/proxy/proxy_candidate.h"
#include "core/scene/scene.h"
#include "geometry/probe_proxies/proxy_build_options.h"
#include "plugin/jobs/job_progress.h"
#include "plugin/jobs/scene_input.h"

#include <filesystem>
#include <vector>

namespace probeproxy::jobs {

struct BuildJobOptions {
  SceneInput input;
  std::filesystem::path outFolder;  // proxies.json + proxies.glb; empty: nothing is written
  int threads = 0;                  // 0: all cores
  ProxyBuildOptions proxy;

  void check() const;  // throws InputError naming the option at fault
};

struct BuildJobResult {
  Scene scene;
  std::vector<ProbeProxyBuild> builds;  // scene order
  std::filesystem::path proxiesJson;    // written, or empty
};

// Checks the options, reads everything, builds, and writes the export only at the end (so bad
// input leaves no file behind).
BuildJobResult runBuildJob(const BuildJobOptions& options, const Progress& progress = {});

}  // namespace probeproxy::jobs
