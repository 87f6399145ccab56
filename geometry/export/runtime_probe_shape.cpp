#include "geometry/export/runtime_probe_shape.h"

#include "core/errors/input_error.h"

namespace probeproxy {

ProxyShape runtimeProbeShape(const RuntimeProbe& p, const std::filesystem::path& file) {
  auto missing = [&](const char* what) {
    return InputError(file, "probe '" + p.name + "' of kind " + p.kind + " has no " + what);
  };
  if (p.kind == "infinite") return InfiniteShape{};
  if (p.kind == "cheap_k") {
    if (!p.kPerMeter) throw missing("k");
    return CheapKShape{*p.kPerMeter};
  }
  if (p.kind == "sphere") {
    if (!p.sphere) throw missing("sphere");
    return *p.sphere;
  }
  if (p.kind == "aabb" || p.kind == "obb") {
    if (!p.box) throw missing("box");
    return *p.box;
  }
  if (p.kind == "convex") {
    if (p.convex.planes.empty()) throw missing("planes");
    return p.convex;
  }
  throw InputError(file, "probe '" + p.name + "' has an unknown proxy kind '" + p.kind + "'");
}

}  // namespace probeproxy
