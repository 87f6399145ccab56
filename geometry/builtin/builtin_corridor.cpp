#include "geometry/builtin/builtin_corridor.h"

#include "geometry/builtin/box_room.h"

namespace probeproxy {

BuiltinLevel builtinCorridor() {
  const glm::dvec3 lo(-9.0, -1.5, 0.0);
  const glm::dvec3 hi(9.0, 1.5, 3.0);
  const glm::dvec3 roomCenter = 0.5 * (lo + hi);
  const glm::dvec3 roomHalf = 0.5 * (hi - lo);

  BuiltinLevel built;
  built.meshFileName = "corridor.obj";
  built.level = boxRoom(glm::vec3(lo), glm::vec3(hi), "corridor");
  built.scene.fileUp = UpAxis::Z;
  built.scene.level.push_back({built.meshFileName, built.meshFileName, UpAxis::Z, false, {}});

  const char* names[3] = {"corridor_a", "corridor_b", "corridor_c"};
  for (int i = 0; i < 3; ++i) {
    const double x = -6.0 + 6.0 * i;
    Probe probe;
    probe.name = names[i];
    probe.captureMeters = {x, 0.0, 1.6};
    // Each probe owns its third of the corridor fully and fades out over a metre into its
    // neighbours', so walking along the corridor never pops.
    BoxInfluence influence;
    influence.centerMeters = {x, 0.0, roomCenter.z};
    influence.halfExtentsMeters = {4.0, roomHalf.y, roomHalf.z};
    influence.innerHalfExtentsMeters = {2.5, roomHalf.y, roomHalf.z};
    probe.influence = influence;
    probe.proxy = AuthoredBox{roomCenter, roomHalf};
    probe.reflectionPlanes.push_back({{x, 0.0, 0.0}, {0.0, 0.0, 1.0}});
    built.scene.probes.push_back(std::move(probe));
  }
  return built;
}

}  // namespace probeproxy
