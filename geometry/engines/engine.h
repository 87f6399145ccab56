#pragma once
// The renderers whose reflection probes probeproxy models (`survey --engine`): which probes
// reach a shaded point, with what weight, and what each one's reflection is projected on.
// geometry/engines/<name>_model.cpp holds each engine's rules, each citing the engine's own
// source; docs/engines.md says the same in prose.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

enum class Engine {
  Generic,    // probeproxy's own: convex proxies, Lagarde's or Enlighten's blend
  Unity,      // Unity's built-in pipeline, deferred reflections (per pixel)
  UnityHdrp,  // Unity HDRP: influence and proxy volumes apart, per-face blend distances
  Unreal,     // Unreal Engine box (and sphere) reflection captures
  Godot3,     // Godot 3 GLES3 ReflectionProbe
  Godot4,     // Godot 4 Forward+ ReflectionProbe with blend_distance
  Bevy,       // Bevy light probes with parallax correction
  Eevee,      // Blender 3.x EEVEE reflection cubemaps
};

inline constexpr std::array<Engine, 8> kEngines = {
    Engine::Generic, Engine::Unity,  Engine::UnityHdrp, Engine::Unreal,
    Engine::Godot3,  Engine::Godot4, Engine::Bevy,      Engine::Eevee};

// "generic", "unity", "unity-hdrp", "unreal", "godot3", "godot4", "bevy", "eevee".
std::string_view engineName(Engine engine);
std::optional<Engine> engineFromName(std::string_view name);

// engineFromName, or InputError naming `option` and listing the names.
Engine parseEngine(std::string_view name, const std::string& option = "--engine");

// A comma-separated list of names, or "all" (every engine but generic), in the order given,
// each once; InputError as parseEngine.
std::vector<Engine> parseEngines(std::string_view names, const std::string& option = "--engine");

}  // namespace probeproxy
