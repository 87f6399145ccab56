#pragma once
// One reflection probe as the scene file describes it. World frame (Z up), metres.

#include "core/scene/influence_volume.h"
#include "core/scene/proxy_spec.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace probeproxy {

struct ReflectionPlane {  // a planar receiver, e.g. a mirror floor
  glm::dvec3 pointMeters{0.0};
  glm::dvec3 normal{0, 0, 1};  // unit
};

struct Probe {
  std::string name;               // unique within the scene, non-empty
  glm::dvec3 captureMeters{0.0};  // the cubemap's centre
  InfluenceVolume influence;
  ProxySpec proxy;
  std::optional<std::string> cubemap;  // pattern as written, `{face}` = px nx py ny pz nz
  std::vector<ReflectionPlane> reflectionPlanes;
};

}  // namespace probeproxy
