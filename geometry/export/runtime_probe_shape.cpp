#include "geometry/export/runtime_probe_shape.h"

#include "core/errors/input_error.h"

namespace probeproxy {

ProxyShape runtimeProbeShape(const RuntimeProbe& p, const std::filesystem::path& file) {
  auto missing = [&](const char* what) {
    return InputError(file, "probe '" + p.name + "' of kind " + std::string(methodName(p.method)) +
                                " has no " + what);
  };
  switch (p.method) {
    case Method::Infinite:
      return InfiniteShape{};
    case Method::CheapK:
      if (!p.kPerMeter) throw missing("k");
      return CheapKShape{*p.kPerMeter};
    case Method::Sphere:
      if (!p.sphere) throw missing("sphere");
      return *p.sphere;
    case Method::Aabb:
    case Method::Obb:
      if (!p.box) throw missing("box");
      return *p.box;
    case Method::Convex:
      if (p.convex.planes.empty()) throw missing("planes");
      return p.convex;
  }
  throw InputError(file, "probe '" + p.name + "' has an unknown proxy kind");
}

}  // namespace probeproxy
