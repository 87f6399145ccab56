#pragma once
// The entity lump of a Quake 3 BSP: plain text, `{ "key" "value" ... }` blocks, one per
// entity (worldspawn first). Parsed into key/value lists, and the entities a probe layout
// needs picked out: player spawn points and lights, in the world frame (Z up, metres).

#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace probeproxy {

struct BspEntity {
  std::vector<std::pair<std::string, std::string>> keys;  // in file order, as written

  // The first value of `key`, if there is one.
  std::optional<std::string> value(std::string_view key) const;
  std::string classname() const;  // "" when it has none
};

// Where a player can start: `info_player_start`, `info_player_deathmatch`, the team spawns
// (`info_player_team1`..`4`, and Quake 3's `team_CTF_redplayer`, `team_CTF_bluespawn`...).
// `info_player_intermission` is a camera for the score screen, not a spawn point.
struct BspSpawnPoint {
  std::string classname;
  glm::dvec3 originMeters{0.0};   // world frame; the player's origin, about 0.75 m over its feet
  glm::dvec3 anglesDegrees{0.0};  // pitch, yaw, roll ("angles", or "angle" as the yaw)
};

// A point light (`light` entities; q3map bakes them, the runtime never sees them).
struct BspLight {
  glm::dvec3 originMeters{0.0};
  double intensity = 300.0;       // "light" key, q3map's units; 300 when absent, as q3map
  glm::dvec3 color{1.0};          // "_color" as written (q3map normalizes it)
  glm::dvec3 anglesDegrees{0.0};  // pitch, yaw, roll, for spot lights that have them
};

// Throws InputError(file, "lump 0 (entities): ...") on text it cannot read (an unclosed
// quote or brace, a key without a value).
std::vector<BspEntity> parseBspEntities(std::string_view text, const std::filesystem::path& file);

// Throws InputError naming the entity when its origin or angles are not numbers.
std::vector<BspSpawnPoint> bspSpawnPoints(const std::vector<BspEntity>& entities,
                                          double metersPerUnit, const std::filesystem::path& file);
std::vector<BspLight> bspLights(const std::vector<BspEntity>& entities, double metersPerUnit,
                                const std::filesystem::path& file);

}  // namespace probeproxy
