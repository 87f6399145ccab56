#pragma once
// Deterministic, human-friendly JSON text for files people also edit by hand (the scene file).
// nlohmann's dump() puts either everything on one line or every number on its own line; a
// scene file reads best with the top level and each probe one member per line, and every
// member's value on one line, wrapped at the column limit only when it must be. This is that
// layout, with the numbers already spelled by the caller (see jsonCoordinate).
//
// Layout rules (they make docs/cli_and_formats.md's example a fixed point):
//   - a container built with `oneItemPerLine` puts each item on its own line, indented by 2;
//   - any other container is written inline: `[1.0, 2.0]` for scalars, `[ {...}, {...} ]` and
//     `{ "a": 1, "b": 2 }` (padded) otherwise; if that would pass the column limit it breaks
//     after a comma and continues under its first item.

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace probeproxy {

struct JsonLayoutMember;

struct JsonLayoutValue {
  enum class Kind { Scalar, Array, Object };
  Kind kind = Kind::Scalar;
  std::string scalarText;  // Kind::Scalar: the JSON token exactly as it is to be written
  std::vector<JsonLayoutValue> elements;  // Kind::Array
  // Kind::Object, in order. A struct of its own rather than std::pair: a vector may hold a
  // type not yet complete, a pair may not (clang's libstdc++ checks refuse it).
  std::vector<JsonLayoutMember> members;
  bool oneItemPerLine = false;
};

struct JsonLayoutMember {
  std::string key;
  JsonLayoutValue value;
};

inline constexpr std::size_t kJsonColumnLimit = 100;  // the code's own .clang-format limit

// Scalars.
JsonLayoutValue jsonString(std::string_view text);  // escaped; invalid UTF-8 becomes U+FFFD
JsonLayoutValue jsonInteger(long long value);
// A coordinate-like number, rounded so that unit-conversion noise (x * 0.01 / 0.01) never
// shows: to 1e-9 when |value| < 1e6, to 15 significant digits above, then the shortest
// decimal that reads back to it, always with a `.0` or an exponent so it stays a float.
// Non-finite values become `null` (which no reader of ours accepts: see writeSceneFile).
JsonLayoutValue jsonCoordinate(double value);
double jsonRoundedCoordinate(double value);  // the number jsonCoordinate spells
// A number printed as the shortest decimal that reads back to exactly `value` (no rounding):
// for scale factors such as meters_per_unit, where 1e-12 is a legitimate value.
JsonLayoutValue jsonExactNumber(double value);
// A factor whose size depends on the file's unit (cheap_k's k, per unit length), rounded to 12
// significant digits so that unit-conversion noise never shows, then spelled as above.
JsonLayoutValue jsonFactor(double value);

// Containers.
JsonLayoutValue jsonArray(std::vector<JsonLayoutValue> elements, bool oneItemPerLine = false);
JsonLayoutValue jsonObject(std::vector<std::pair<std::string, JsonLayoutValue>> members,
                           bool oneItemPerLine = false);

// The whole document, ending in a newline.
std::string layoutJson(const JsonLayoutValue& root, std::size_t columnLimit = kJsonColumnLimit);

}  // namespace probeproxy
