#pragma once
// A probe whose box influence is exactly the room [lo, hi], fully inside its inner range: the
// proxy build's test fixture.

#include "core/scene/probe.h"

namespace probeproxy {

inline Probe probeAt(glm::dvec3 capture, glm::dvec3 lo, glm::dvec3 hi) {
  Probe probe;
  probe.name = "probe";
  probe.captureMeters = capture;
  BoxInfluence influence;
  influence.centerMeters = 0.5 * (lo + hi);
  influence.halfExtentsMeters = influence.innerHalfExtentsMeters = 0.5 * (hi - lo);
  probe.influence = influence;
  return probe;
}

}  // namespace probeproxy
