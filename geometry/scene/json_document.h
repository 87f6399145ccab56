#pragma once
// Parsing JSON that a person wrote, for validation. nlohmann's parse() gives the document but
// loses what an error message needs: a syntax error's line and column (it reports a byte
// offset), the JSON path of a number too large for a double (1e400 is valid JSON but not a
// finite double), and duplicate member names, which it silently resolves to the last one.
// Internal to geometry/scene: the public headers stay free of nlohmann.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace probeproxy {

// One problem in the document. what() is `<JSON path>: <problem>` or
// `invalid JSON at line L, column C: <problem>`, without a file name: the caller knows it.
class JsonProblem : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The limits of the JSON probeproxy reads (scene files, proxies.json): every real file is far
// inside them, and a hostile one is refused in time linear in its size, before it can exhaust
// memory or the stack.
inline constexpr std::size_t kMaxJsonBytes = std::size_t(64) << 20;  // 64 MiB
inline constexpr std::size_t kMaxJsonDepth = 64;                     // nested arrays/objects

// The document, or JsonProblem. Lines and columns count from 1; columns count characters
// (UTF-8 code points), as editors do. Text over kMaxJsonBytes or nested deeper than
// kMaxJsonDepth is refused.
nlohmann::json parseJsonDocument(std::string_view text);

// A JSON file's bytes, for parseJsonDocument. Throws InputError naming the file: cannot open,
// cannot read (a folder), or larger than kMaxJsonBytes (checked before reading).
std::string readJsonFile(const std::filesystem::path& file);

// JSON paths as error messages spell them: `$`, `$.probes[1].influence.radius`, and
// `$["odd key"]` for keys that are not plain identifiers.
std::string jsonMemberPath(const std::string& objectPath, std::string_view key);
std::string jsonIndexPath(const std::string& arrayPath, std::size_t index);

// A short, one-line rendering of a value for `expected ..., got <value>`: `-2`, `"abc"`,
// `[1, 0, 1]`; long values are cut to about 60 characters and end in `...`.
std::string describeJson(const nlohmann::json& value);

}  // namespace probeproxy
