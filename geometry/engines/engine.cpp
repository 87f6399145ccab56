#include "geometry/engines/engine.h"

#include "core/errors/input_error.h"

#include <algorithm>

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

std::vector<Engine> parseEngines(std::string_view names, const std::string& option) {
  std::vector<Engine> engines;
  if (names == "all") {
    engines.assign(kEngines.begin() + 1, kEngines.end());
    return engines;
  }
  std::size_t start = 0;
  while (start <= names.size()) {
    const std::size_t comma = std::min(names.find(',', start), names.size());
    const Engine engine = parseEngine(names.substr(start, comma - start), option);
    if (std::find(engines.begin(), engines.end(), engine) == engines.end())
      engines.push_back(engine);
    start = comma + 1;
  }
  return engines;
}

}  // namespace probeproxy
