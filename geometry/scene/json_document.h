#pragma once
// Parsing JSON that a person wrote, for validation. nlohmann's parse() gives the document but
// loses what an error message needs: a syntax error's line and column (it reports a byte
// offset), the JSON path of a number too large for a double (1e400 is valid JSON but not a
// finite double), and duplicate member names, which it silently resolves to the last one.
// Internal to geometry/scene: the public headers stay free of nlohmann.

#include <nlohmann/json.hpp>

#include <cstddef>
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

// The document, or JsonProblem. Lines and columns count from 1; columns count characters
// (UTF-8 code points), as editors do.
nlohmann::json parseJsonDocument(std::string_view text);

// JSON paths as error messages spell them: `$`, `$.probes[1].influence.radius`, and
// `$["odd key"]` for keys that are not plain identifiers.
std::string jsonMemberPath(const std::string& objectPath, std::string_view key);
std::string jsonIndexPath(const std::string& arrayPath, std::size_t index);

// A short, one-line rendering of a value for `expected ..., got <value>`: `-2`, `"abc"`,
// `[1, 0, 1]`; long values are cut to about 60 characters and end in `...`.
std::string describeJson(const nlohmann::json& value);

}  // namespace probeproxy
