#pragma once
// What a layout's final proxy builds send to wherever they run (another process, a Dask worker)
// and back. Out: per probe all that buildLayoutProxy reads of it, its name, capture point and
// influence volume, the radius its candidate was fitted on, and the volumes it blends with.
// Back: the build whole, every candidate with its shape and figures, the kept one, the timings
// and findings, so that the export, the engine presets and the reports read what a build in
// this process would have made.
// Bytes: a header ("PPBT" or "PPBB", version), then the fields in order, little-endian, doubles
// as their bits (wire_bytes.h).

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

struct ProxyBuildTask {
  Probe probe;  // name, captureMeters and influence travel; nothing else of it is read
  double candidateFitMeters = 0.0;  // as buildLayoutProxy's
  // Its BlendNeighbourhood (layout_proxy.h): the volumes reaching the probe's, its own at
  // blendIndex.
  std::vector<InfluenceVolume> blendVolumes;
  int blendIndex = -1;
};

std::string packProxyBuildTask(const ProxyBuildTask& task);
std::string packProxyBuild(const ProbeProxyBuild& build);

// Each throws InputError ("proxy build wire: ...") naming what is wrong with bytes its pack
// did not write.
ProxyBuildTask unpackProxyBuildTask(std::string_view bytes);
ProbeProxyBuild unpackProxyBuild(std::string_view bytes);

}  // namespace probeproxy
