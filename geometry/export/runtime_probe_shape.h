#pragma once
// The proxy shape a runtime export's probe is looked up through: what `correct`, `blend` and
// `survey` measure when they are given a proxies.json.

#include "core/proxy/proxy_shape.h"
#include "geometry/export/runtime_export.h"

namespace probeproxy {

// By `kind`: infinite, cheap_k (k), sphere, aabb/obb (box), convex (planes). Throws
// InputError naming `file` when the kind is unknown or its data is missing.
ProxyShape runtimeProbeShape(const RuntimeProbe& probe, const std::filesystem::path& file);

}  // namespace probeproxy
