#include "geometry/engines/engine.h"

#include "core/errors/input_error.h"

namespace probeproxy {

std::string_view engineName(Engine engine) {
  switch (engine) {
    case Engine::Generic:
      return "generic";
    case Engine::Unity:
      return "unity";
    case Engine::UnityHdrp:
      return "unity-hdrp";
    case Engine::Unreal:
      return "unreal";
    case Engine::Godot3:
      return "godot3";
    case Engine::Godot4:
      return "godot4";
    case Engine::Bevy:
      return "bevy";
    case Engine::Eevee:
      return "eevee";
  }
  return "generic";
}

std::optional<Engine> engineFromName(std::string_view name) {
  for (const Engine engine : kEngines)
    if (engineName(engine) == name) return engine;
  return std::nullopt;
}

Engine parseEngine(std::string_view name, const std::string& option) {
  if (const std::optional<Engine> engine = engineFromName(name)) return *engine;
  std::string names;
  for (const Engine engine : kEngines) {
    if (!names.empty()) names += ", ";
    names += engineName(engine);
  }
  throw InputError(option, "expected one of " + names + ", got '" + std::string(name) + "'");
}

}  // namespace probeproxy
