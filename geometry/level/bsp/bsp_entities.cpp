#include "geometry/level/bsp/bsp_entities.h"

#include "core/errors/input_error.h"
#include "core/scene/scene_limits.h"
#include "geometry/level/bsp/bsp_lumps.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace probeproxy {

namespace {

[[noreturn]] void failEntities(const std::filesystem::path& file, const std::string& problem) {
  throw InputError(file, bspLumpName(BspLump::Entities) + ": " + problem);
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\0'; }

// Tokens as Quake 3's COM_Parse reads them: quoted strings, braces, and bare words; `//`
// comments skipped. Returns nullopt at the end of the text.
class EntityTokens {
 public:
  EntityTokens(std::string_view text, const std::filesystem::path& file)
      : text_(text), file_(file) {}

  std::optional<std::string> next() {
    skipSpaceAndComments();
    if (at_ >= text_.size()) return std::nullopt;
    const char c = text_[at_];
    if (c == '{' || c == '}') {
      ++at_;
      return std::string(1, c);
    }
    if (c == '"') {
      const std::size_t close = text_.find('"', at_ + 1);
      if (close == std::string_view::npos) {
        failEntities(file_, "unclosed quote at byte " + std::to_string(at_));
      }
      std::string token(text_.substr(at_ + 1, close - at_ - 1));
      at_ = close + 1;
      return token;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && !isSpace(text_[at_]) && text_[at_] != '"' && text_[at_] != '{' &&
           text_[at_] != '}') {
      ++at_;
    }
    return std::string(text_.substr(start, at_ - start));
  }

  std::size_t at() const { return at_; }

 private:
  void skipSpaceAndComments() {
    while (at_ < text_.size()) {
      if (isSpace(text_[at_])) {
        ++at_;
      } else if (text_.substr(at_, 2) == "//") {
        const std::size_t end = text_.find('\n', at_);
        at_ = end == std::string_view::npos ? text_.size() : end;
      } else {
        break;
      }
    }
  }

  std::string_view text_;
  const std::filesystem::path& file_;
  std::size_t at_ = 0;
};

std::string describeEntity(const BspEntity& entity, std::size_t index) {
  const std::string name = entity.classname();
  return "entity " + std::to_string(index) + (name.empty() ? "" : " (" + name + ")");
}

// "x y z": three finite numbers, or nullopt.
std::optional<glm::dvec3> threeNumbers(const std::string& text) {
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  glm::dvec3 v;
  if (!(in >> v.x >> v.y >> v.z)) return std::nullopt;
  std::string rest;
  if (in >> rest) return std::nullopt;
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return std::nullopt;
  return v;
}

std::optional<double> oneNumber(const std::string& text) {
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  double x;
  if (!(in >> x) || !std::isfinite(x)) return std::nullopt;
  std::string rest;
  if (in >> rest) return std::nullopt;
  return x;
}

glm::dvec3 vectorKey(const BspEntity& entity, std::size_t index, const char* key,
                     glm::dvec3 fallback, const std::filesystem::path& file) {
  const std::optional<std::string> text = entity.value(key);
  if (!text) return fallback;
  const std::optional<glm::dvec3> v = threeNumbers(*text);
  if (!v) {
    failEntities(file, describeEntity(entity, index) + " " + key + " \"" + *text +
                           "\" is not three numbers");
  }
  return *v;
}

double numberKey(const BspEntity& entity, std::size_t index, const char* key, double fallback,
                 const std::filesystem::path& file) {
  const std::optional<std::string> text = entity.value(key);
  if (!text) return fallback;
  const std::optional<double> x = oneNumber(*text);
  if (!x) {
    failEntities(file,
                 describeEntity(entity, index) + " " + key + " \"" + *text + "\" is not a number");
  }
  return *x;
}

// "angles" (pitch yaw roll) when present, else "angle" as the yaw, as the game reads them.
glm::dvec3 anglesOf(const BspEntity& entity, std::size_t index, const std::filesystem::path& file) {
  if (entity.value("angles")) return vectorKey(entity, index, "angles", {}, file);
  return {0.0, numberKey(entity, index, "angle", 0.0, file), 0.0};
}

bool isSpawnPoint(const std::string& classname) {
  if (classname == "info_player_intermission") return false;
  if (classname.rfind("info_player_", 0) == 0) return true;
  // Quake 3 Team Arena's CTF spawns: team_CTF_redplayer/blueplayer (first spawn) and
  // team_CTF_redspawn/bluespawn (respawn).
  return classname.rfind("team_CTF_", 0) == 0 &&
         (classname.ends_with("player") || classname.ends_with("spawn"));
}

}  // namespace

std::optional<std::string> BspEntity::value(std::string_view key) const {
  for (const auto& [k, v] : keys) {
    if (k == key) return v;
  }
  return std::nullopt;
}

std::string BspEntity::classname() const { return value("classname").value_or(""); }

std::vector<BspEntity> parseBspEntities(std::string_view text, const std::filesystem::path& file) {
  EntityTokens tokens(text, file);
  std::vector<BspEntity> entities;
  while (const std::optional<std::string> open = tokens.next()) {
    if (*open != "{") {
      failEntities(file, "expected '{' to start entity " + std::to_string(entities.size()) +
                             ", got \"" + *open + "\" at byte " + std::to_string(tokens.at()));
    }
    BspEntity entity;
    for (;;) {
      const std::optional<std::string> key = tokens.next();
      if (!key) {
        failEntities(file, "entity " + std::to_string(entities.size()) + " is not closed by '}'");
      }
      if (*key == "}") break;
      const std::optional<std::string> value = tokens.next();
      if (!value || *value == "}" || *value == "{") {
        failEntities(file, "entity " + std::to_string(entities.size()) + " key \"" + *key +
                               "\" has no value");
      }
      entity.keys.emplace_back(*key, *value);
    }
    entities.push_back(std::move(entity));
  }
  return entities;
}

namespace {

// An entity's origin in metres, within the scene limit: a spawn point seeds rays and flood
// fills, and one at 1e20 m reached Embree as an invalid ray.
glm::dvec3 originKey(const BspEntity& entity, std::size_t index, double metersPerUnit,
                     const std::filesystem::path& file) {
  const glm::dvec3 meters = vectorKey(entity, index, "origin", {}, file) * metersPerUnit;
  if (std::abs(meters.x) > kMaxSceneMeters || std::abs(meters.y) > kMaxSceneMeters ||
      std::abs(meters.z) > kMaxSceneMeters) {
    std::ostringstream problem;
    problem << describeEntity(entity, index) << " origin \"" << *entity.value("origin")
            << "\" is past " << kMaxSceneMeters
            << " m from the map's origin (the limit of a scene)";
    failEntities(file, problem.str());
  }
  return meters;
}

}  // namespace

std::vector<BspSpawnPoint> bspSpawnPoints(const std::vector<BspEntity>& entities,
                                          double metersPerUnit, const std::filesystem::path& file) {
  std::vector<BspSpawnPoint> spawns;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const BspEntity& entity = entities[i];
    const std::string classname = entity.classname();
    if (!isSpawnPoint(classname)) continue;
    BspSpawnPoint spawn;
    spawn.classname = classname;
    spawn.originMeters = originKey(entity, i, metersPerUnit, file);
    spawn.anglesDegrees = anglesOf(entity, i, file);
    spawns.push_back(std::move(spawn));
  }
  return spawns;
}

std::vector<BspLight> bspLights(const std::vector<BspEntity>& entities, double metersPerUnit,
                                const std::filesystem::path& file) {
  std::vector<BspLight> lights;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const BspEntity& entity = entities[i];
    if (entity.classname() != "light") continue;
    BspLight light;
    light.originMeters = originKey(entity, i, metersPerUnit, file);
    light.intensity = numberKey(entity, i, "light", 300.0, file);
    light.color = vectorKey(entity, i, "_color", glm::dvec3(1.0), file);
    light.anglesDegrees = anglesOf(entity, i, file);
    lights.push_back(std::move(light));
  }
  return lights;
}

}  // namespace probeproxy
