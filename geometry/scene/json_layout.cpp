#include "geometry/scene/json_layout.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>

namespace probeproxy {

namespace {

// to_chars/from_chars, not printf/strtod: the add-on runs us inside Blender, whose locale may
// spell the decimal point as a comma.
double roundedToSignificantDigits(double value, int digits) {
  char buffer[64];
  const auto printed = std::to_chars(buffer, buffer + sizeof(buffer), value,
                                     std::chars_format::scientific, digits - 1);
  double rounded = value;
  std::from_chars(buffer, printed.ptr, rounded, std::chars_format::scientific);
  return rounded;
}

using Kind = JsonLayoutValue::Kind;

std::string shortestDecimal(double value, std::chars_format format) {
  char buffer[400];  // fixed notation of 1e308 needs 309 digits
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value, format);
  std::string text(buffer, result.ptr);
  // Keep it a float token, so a reader that distinguishes integers does not change its type.
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

JsonLayoutValue scalar(std::string text) {
  JsonLayoutValue value;
  value.scalarText = std::move(text);
  return value;
}

std::string spaces(std::size_t count) { return std::string(count, ' '); }

std::size_t columnAfter(const std::string& text, std::size_t startColumn) {
  const std::size_t lastBreak = text.rfind('\n');
  if (lastBreak == std::string::npos) return startColumn + text.size();
  return text.size() - lastBreak - 1;
}

bool isContainer(const JsonLayoutValue& value) { return value.kind != Kind::Scalar; }

std::size_t itemCount(const JsonLayoutValue& value) {
  return value.kind == Kind::Array ? value.elements.size() : value.members.size();
}

// Arrays of plain numbers read best unpadded (`[1.0, 2.0, 3.0]`); anything holding braces
// gets a space inside its own brackets so the nesting is visible (`[ { ... } ]`).
bool isPadded(const JsonLayoutValue& value) {
  if (value.kind == Kind::Object) return true;
  for (const JsonLayoutValue& element : value.elements) {
    if (isContainer(element)) return true;
  }
  return false;
}

std::string openerOf(const JsonLayoutValue& value) {
  const char* bracket = value.kind == Kind::Object ? "{" : "[";
  return isPadded(value) ? std::string(bracket) + " " : std::string(bracket);
}

std::string closerOf(const JsonLayoutValue& value) {
  const char* bracket = value.kind == Kind::Object ? "}" : "]";
  return isPadded(value) ? std::string(" ").append(bracket) : std::string(bracket);
}

std::string keyPrefix(const std::string& key) { return jsonString(key).scalarText + ": "; }

std::string flat(const JsonLayoutValue& value) {
  if (value.kind == Kind::Scalar) return value.scalarText;
  if (itemCount(value) == 0) return value.kind == Kind::Object ? "{}" : "[]";
  std::string text = openerOf(value);
  for (std::size_t i = 0; i < itemCount(value); ++i) {
    if (i > 0) text += ", ";
    text += value.kind == Kind::Object
                ? keyPrefix(value.members[i].key) + flat(value.members[i].value)
                : flat(value.elements[i]);
  }
  return text + closerOf(value);
}

class Layout {
 public:
  explicit Layout(std::size_t columnLimit) : limit_(columnLimit) {}

  // `value` starts at `column` on a line indented by `lineIndent`; `suffixWidth` characters
  // (a comma, closing brackets) will follow its last character on the same line.
  std::string render(const JsonLayoutValue& value, std::size_t column, std::size_t lineIndent,
                     std::size_t suffixWidth) const {
    if (value.kind == Kind::Scalar || itemCount(value) == 0) return flat(value);
    if (value.oneItemPerLine) return renderOnePerLine(value, lineIndent);
    return renderInline(value, column, suffixWidth);
  }

 private:
  std::string renderOnePerLine(const JsonLayoutValue& value, std::size_t lineIndent) const {
    const bool isObject = value.kind == Kind::Object;
    const std::size_t itemIndent = lineIndent + 2;
    std::string text = isObject ? "{\n" : "[\n";
    for (std::size_t i = 0; i < itemCount(value); ++i) {
      const bool last = i + 1 == itemCount(value);
      const std::size_t suffixWidth = last ? 0 : 1;
      text += spaces(itemIndent);
      if (isObject) {
        const std::string prefix = keyPrefix(value.members[i].key);
        text += prefix +
                render(value.members[i].value, itemIndent + prefix.size(), itemIndent, suffixWidth);
      } else {
        text += render(value.elements[i], itemIndent, itemIndent, suffixWidth);
      }
      text += last ? "\n" : ",\n";
    }
    return text + spaces(lineIndent) + (isObject ? "}" : "]");
  }

  // Greedy fill: as many items per line as fit, continuing under the first item.
  std::string renderInline(const JsonLayoutValue& value, std::size_t column,
                           std::size_t suffixWidth) const {
    const std::string whole = flat(value);
    if (column + whole.size() + suffixWidth <= limit_) return whole;

    const bool isObject = value.kind == Kind::Object;
    const std::string opener = openerOf(value);
    const std::string closer = closerOf(value);
    const std::size_t continuationColumn = column + opener.size();
    std::string text = opener;
    std::size_t current = continuationColumn;
    bool firstOnLine = true;
    for (std::size_t i = 0; i < itemCount(value); ++i) {
      const bool last = i + 1 == itemCount(value);
      const std::size_t trailingWidth = last ? closer.size() + suffixWidth : 1;
      const std::string prefix = isObject ? keyPrefix(value.members[i].key) : std::string();
      const JsonLayoutValue& item = isObject ? value.members[i].value : value.elements[i];
      std::string itemText = prefix + flat(item);

      if (!firstOnLine && current + 1 + itemText.size() + trailingWidth > limit_) {
        text += '\n';
        text += spaces(continuationColumn);
        current = continuationColumn;
        firstOnLine = true;
      }
      if (!firstOnLine) {
        text += " ";
        current += 1;
      }
      if (current + itemText.size() + trailingWidth > limit_ && isContainer(item)) {
        itemText =
            prefix + render(item, current + prefix.size(), continuationColumn, trailingWidth);
      }
      text += itemText;
      current = columnAfter(itemText, current);
      text += last ? closer : ",";
      current += last ? closer.size() : 1;
      firstOnLine = false;
    }
    return text;
  }

  std::size_t limit_;
};

}  // namespace

JsonLayoutValue jsonString(std::string_view text) {
  return scalar(nlohmann::json(std::string(text))
                    .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

JsonLayoutValue jsonInteger(long long value) { return scalar(std::to_string(value)); }

double jsonRoundedCoordinate(double value) {
  if (!std::isfinite(value)) return value;
  double rounded = value;
  if (std::abs(value) < 1e6) {
    // value * 1e9 < 1e15 < 2^53: the rounding is exact integer arithmetic.
    rounded = std::round(value * 1e9) / 1e9;
  } else {
    rounded = roundedToSignificantDigits(value, 15);
  }
  return rounded == 0.0 ? 0.0 : rounded;  // no "-0.0" from a conversion such as (x, -z, y)
}

JsonLayoutValue jsonCoordinate(double value) {
  if (!std::isfinite(value)) return scalar("null");
  const double rounded = jsonRoundedCoordinate(value);
  const bool fixedReadsWell = std::abs(rounded) < 1e15;
  return scalar(shortestDecimal(
      rounded, fixedReadsWell ? std::chars_format::fixed : std::chars_format::scientific));
}

JsonLayoutValue jsonExactNumber(double value) {
  if (!std::isfinite(value)) return scalar("null");
  if (value == 0.0) value = 0.0;
  const bool fixedReadsWell = std::abs(value) >= 1e-6 && std::abs(value) < 1e15;
  return scalar(shortestDecimal(
      value, fixedReadsWell ? std::chars_format::fixed : std::chars_format::scientific));
}

JsonLayoutValue jsonFactor(double value) {
  if (!std::isfinite(value)) return scalar("null");
  return jsonExactNumber(roundedToSignificantDigits(value, 12));
}

JsonLayoutValue jsonArray(std::vector<JsonLayoutValue> elements, bool oneItemPerLine) {
  JsonLayoutValue value;
  value.kind = Kind::Array;
  value.elements = std::move(elements);
  value.oneItemPerLine = oneItemPerLine;
  return value;
}

JsonLayoutValue jsonObject(std::vector<std::pair<std::string, JsonLayoutValue>> members,
                           bool oneItemPerLine) {
  JsonLayoutValue value;
  value.kind = Kind::Object;
  for (auto& [key, member] : members) value.members.push_back({std::move(key), std::move(member)});
  value.oneItemPerLine = oneItemPerLine;
  return value;
}

std::string layoutJson(const JsonLayoutValue& root, std::size_t columnLimit) {
  return Layout(columnLimit).render(root, 0, 0, 0) + "\n";
}

}  // namespace probeproxy
