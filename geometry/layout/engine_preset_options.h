#pragma once
// Which of each probe's presets an engine renders the level best with, or none. A layout
// places probes for its own blend, where each probe serves its own influence volume and
// projects on its own convex proxy; an engine whose box is both where a probe applies and what
// its reflection is projected on (Unity, Unreal, Godot, EEVEE) lets every box that reaches a
// point take part by its own rule: the smallest box on top, the average of all, the farthest
// first. Two probes of one room then compete for the whole room, and the rule may put first
// the one with the worse box, or average the two lookups; a box fitted to the floor a probe
// serves may reach rooms it does not. So per probe the engine may be better served by another
// of the boxes its build fitted (the room's walls from the capture point, the box round what it
// sees, turned or not), or by no probe there at all; every other engine keeps its own choice.
//
// Local search under the engine's own model: while one move (a probe to another of its
// options, or left out) makes the floor that does not get the reflection right (over the
// tolerance, left to the engine's fallback, or shown by probes that cannot see what it
// reflects: what stands in front of it) smaller by at least kLeastOptionGain of the
// floor, the move that makes it smallest is made (ties: the lowest probe, then option). Each
// sample's options, fades and sights are found once; a move re-weighs only the samples its two
// options reach, and re-judges only the probes with an option there.

#include "geometry/engines/engine_model.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/run_survey.h"

#include <span>
#include <vector>

namespace probeproxy {

// A move must gain at least this share of the floor: less is within what a trial floor's few
// samples per cell can tell.
inline constexpr double kLeastOptionGain = 0.0005;

// `model.probes` are the options: option j is one of probe `probeOf[j]`'s presets (probes
// numbered from 0, the options of each in ascending order). `start[p]` is the option probe p
// starts with, -1 for none. Returns, per probe, the option kept, -1 where the engine is better
// without the probe. A model without a separable blend (the generic one) keeps `start`.
// `floor` is the floor the choice is made on (a layout's trial floor). Probes below
// `keptProbes` may take another option but are never left out. `sights`, made for `floor`, keeps
// the rays cast from capture points for other searches and surveys of it.
std::vector<int> chooseEngineOptions(const EngineModel& model, std::span<const int> probeOf,
                                     std::vector<int> start, const SurveyFloor& floor,
                                     const LevelRayCaster& level, double toleranceDeg,
                                     std::size_t keptProbes = 0, CaptureSights* sights = nullptr);

}  // namespace probeproxy
