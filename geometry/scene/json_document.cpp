#include "geometry/scene/json_document.h"

#include "core/errors/input_error.h"
#include "core/io/regular_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace probeproxy {

namespace {

using Json = nlohmann::json;

constexpr std::size_t kDescribeLimit = 60;

bool isUtf8Continuation(char byte) { return (static_cast<unsigned char>(byte) & 0xC0) == 0x80; }

bool isPlainIdentifier(std::string_view key) {
  if (key.empty() || (key[0] >= '0' && key[0] <= '9')) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

std::string dumpScalar(const Json& value) {
  return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string compact(const Json& value) {
  if (value.is_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i > 0) text += ", ";
      text += compact(value[i]);
      if (text.size() > kDescribeLimit) break;  // it is cut below anyway
    }
    return text + "]";
  }
  if (value.is_object()) {
    std::string text = "{";
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (it != value.begin()) text += ", ";
      text += dumpScalar(Json(it.key())) + ": " + compact(it.value());
      if (text.size() > kDescribeLimit) break;
    }
    return text + "}";
  }
  return dumpScalar(value);
}

// "line 3, column 8" for the character nlohmann stopped at. Its position counts the bytes
// read, the offending one included; at the end of the input it points one past the end.
std::string lineAndColumn(std::string_view text, std::size_t bytesRead) {
  const std::size_t index = std::min(bytesRead == 0 ? 0 : bytesRead - 1, text.size());
  std::size_t line = 1;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < index; ++i) {
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    }
  }
  std::size_t column = 1;
  for (std::size_t i = lineStart; i < index; ++i) {
    if (!isUtf8Continuation(text[i])) ++column;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's message without its own prefix and (byte-based) position:
// "[json.exception.parse_error.101] parse error at line 3, column 8: syntax error ..." ->
// "syntax error ...".
std::string syntaxProblem(const std::string& what) {
  const std::size_t position = what.find("parse error at line");
  if (position != std::string::npos) {
    const std::size_t colon = what.find(": ", position);
    if (colon != std::string::npos) return what.substr(colon + 2);
  }
  const std::size_t prefixEnd = what.find("] ");
  return prefixEnd == std::string::npos ? what : what.substr(prefixEnd + 2);
}

// Builds the document like nlohmann's own DOM parser, but knows the JSON path of every value
// as it arrives, so that a problem found during parsing can name it.
class PathTrackingParser final : public nlohmann::json_sax<Json> {
 public:
  explicit PathTrackingParser(std::string_view text) : text_(text) {}

  Json& document() { return root_; }
  const std::optional<std::string>& problem() const { return problem_; }

  bool null() override { return add(Json(nullptr)); }
  bool boolean(bool value) override { return add(Json(value)); }
  bool number_integer(number_integer_t value) override { return add(Json(value)); }
  bool number_unsigned(number_unsigned_t value) override { return add(Json(value)); }
  bool number_float(number_float_t value, const string_t& /*token*/) override {
    return add(Json(value));
  }
  bool string(string_t& value) override { return add(Json(std::move(value))); }
  bool binary(binary_t& value) override { return add(Json::binary(std::move(value))); }

  bool start_object(std::size_t /*size*/) override { return open(Json::object()); }
  bool start_array(std::size_t /*size*/) override { return open(Json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& name) override {
    OpenContainer& top = open_.back();
    if (top.container->contains(name)) {
      problem_ = jsonMemberPath(top.path, name) + ": duplicate member";
      return false;
    }
    top.pendingKey = std::move(name);
    return true;
  }

  bool parse_error(std::size_t bytesRead, const std::string& token,
                   const nlohmann::detail::exception& error) override {
    constexpr int kNumberOverflow = 406;  // nlohmann's out_of_range.406
    if (error.id == kNumberOverflow) {
      problem_ = pathOfNextValue() + ": expected a finite number, got " + token;
    } else {
      problem_ =
          "invalid JSON at " + lineAndColumn(text_, bytesRead) + ": " + syntaxProblem(error.what());
    }
    return false;
  }

 private:
  struct OpenContainer {
    Json* container;  // points into root_; stable while it is open (only its last child grows)
    std::string path;
    std::size_t nextIndex = 0;
    std::string pendingKey;
  };

  std::string pathOfNextValue() const {
    if (open_.empty()) return "$";
    const OpenContainer& top = open_.back();
    return top.container->is_array() ? jsonIndexPath(top.path, top.nextIndex)
                                     : jsonMemberPath(top.path, top.pendingKey);
  }

  Json* insert(Json value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    OpenContainer& top = open_.back();
    if (top.container->is_array()) {
      top.container->push_back(std::move(value));
      ++top.nextIndex;
      return &top.container->back();
    }
    Json& slot = (*top.container)[top.pendingKey];
    slot = std::move(value);
    return &slot;
  }

  bool add(Json value) {
    insert(std::move(value));
    return true;
  }

  bool open(Json emptyContainer) {
    std::string path = pathOfNextValue();
    if (open_.size() >= kMaxJsonDepth) {
      problem_ = path + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                 " arrays and objects (the limit of probeproxy's JSON files)";
      return false;
    }
    Json* container = insert(std::move(emptyContainer));
    open_.push_back(OpenContainer{container, std::move(path), 0, {}});
    return true;
  }

  bool close() {
    open_.pop_back();
    return true;
  }

  std::string_view text_;
  Json root_;
  std::vector<OpenContainer> open_;
  std::optional<std::string> problem_;
};

}  // namespace

nlohmann::json parseJsonDocument(std::string_view text) {
  if (text.size() > kMaxJsonBytes) {
    throw JsonProblem("is " + std::to_string(text.size()) + " bytes; JSON files are read up to " +
                      std::to_string(kMaxJsonBytes >> 20) + " MiB");
  }
  PathTrackingParser parser(text);
  const bool parsed = Json::sax_parse(text.begin(), text.end(), &parser);
  if (!parsed) throw JsonProblem(parser.problem().value_or("invalid JSON"));
  return std::move(parser.document());
}

namespace {

struct FileCloser {
  void operator()(std::FILE* stream) const { std::fclose(stream); }
};

}  // namespace

std::string readJsonFile(const std::filesystem::path& file) {
  // A missing file is fopen's to name, as any other failure to open.
  std::error_code exists;
  if (std::filesystem::exists(file, exists)) requireRegularFile(file, "JSON file");
  const std::unique_ptr<std::FILE, FileCloser> stream(std::fopen(file.c_str(), "rb"));
  if (!stream) throw InputError(file, "cannot open: " + std::generic_category().message(errno));
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (!error && size > kMaxJsonBytes) {
    throw InputError(file, "is " + std::to_string(size) + " bytes; JSON files are read up to " +
                               std::to_string(kMaxJsonBytes >> 20) + " MiB");
  }
  std::string bytes;
  char buffer[1 << 16];
  std::size_t count;
  while ((count = std::fread(buffer, 1, sizeof(buffer), stream.get())) > 0) {
    bytes.append(buffer, count);
    if (bytes.size() > kMaxJsonBytes) break;  // a pipe or a growing file: parse refuses it
  }
  if (std::ferror(stream.get())) {  // e.g. a folder: fopen succeeds, reading does not
    throw InputError(file, "cannot read: " + std::generic_category().message(errno));
  }
  return bytes;
}

std::string jsonMemberPath(const std::string& objectPath, std::string_view key) {
  if (isPlainIdentifier(key)) return objectPath + "." + std::string(key);
  return objectPath + "[" + dumpScalar(Json(std::string(key))) + "]";
}

std::string jsonIndexPath(const std::string& arrayPath, std::size_t index) {
  return arrayPath + "[" + std::to_string(index) + "]";
}

std::string describeJson(const nlohmann::json& value) {
  std::string text = compact(value);
  if (text.size() <= kDescribeLimit) return text;
  std::size_t cut = kDescribeLimit - 3;
  while (cut > 0 && isUtf8Continuation(text[cut])) --cut;  // never split a character
  return text.substr(0, cut) + "...";
}

}  // namespace probeproxy
