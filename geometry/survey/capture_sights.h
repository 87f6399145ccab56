#pragma once
// Whether each sample of one prepared floor has its true hit hidden from a capture point, each
// ray cast once. `layout --engine` surveys one trial floor under every policy of every engine
// and searches each probe's options on it: a probe keeps its capture point under most of its
// boxes and policies, and the ray from it to each sample's true hit was most of that stage (in a
// 20 s sample of silvercity's Godot 3 stage, 75% of the time went to those casts, each made
// again per policy and option).

#include "geometry/engines/engine_model.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/run_survey.h"

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

namespace probeproxy {

class CaptureSights {
 public:
  // The floor must outlive this.
  explicit CaptureSights(const SurveyFloor& floor);

  // The id of each probe's capture point, ids given in order of first sight. Not thread-safe:
  // call before a parallel pass over the samples.
  std::vector<std::uint32_t> idsOf(std::span<const EngineProbe> probes);

  // Whether sample `sample`'s true hit is hidden from capture point `id` (trueHitHiddenFrom),
  // cast on first asking. Thread-safe for calls on different samples.
  bool hidden(const LevelRayCaster& level, std::size_t sample, std::uint32_t id);

 private:
  const SurveyFloor& floor_;
  std::map<std::array<double, 3>, std::uint32_t> ids_;
  std::vector<glm::dvec3> captures_;  // by id
  // Per sample, 2 bits an id: 0 not cast yet, 1 seen, 2 hidden. samples x (24 + ids / 4) bytes:
  // not in layout's memory estimate.
  std::vector<std::vector<std::uint8_t>> known_;
};

}  // namespace probeproxy
