#include "plugin/cli/command_line_values.h"

#include "core/errors/input_error.h"

#include <charconv>
#include <cmath>
#include <string>

namespace probeproxy::cli {

std::vector<double> parseNumberList(std::string_view text, std::size_t count,
                                    std::string_view option) {
  std::string problem = "expected ";
  problem += std::to_string(count);
  problem += " comma-separated numbers, got '";
  problem += text;
  problem += "'";
  std::vector<double> values;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string_view item = text.substr(begin, end - begin);
    double value = 0.0;
    // from_chars takes no leading '+' or spaces: a strict decimal or exponent number.
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() ||
        !std::isfinite(value))
      throw InputError(std::string(option), problem);
    values.push_back(value);
    begin = end + 1;
  }
  if (values.size() != count) throw InputError(std::string(option), problem);
  return values;
}

glm::dvec3 parsePoint(std::string_view text, std::string_view option) {
  const std::vector<double> xyz = parseNumberList(text, 3, option);
  return {xyz[0], xyz[1], xyz[2]};
}

std::optional<ReflectionPlane> parseOptionalPlane(std::string_view text, std::string_view option) {
  if (text.empty()) return std::nullopt;
  const std::vector<double> p = parseNumberList(text, 6, option);
  return ReflectionPlane{{p[0], p[1], p[2]}, {p[3], p[4], p[5]}};  // checked by the job
}

std::uint64_t parseMemorySize(std::string_view text, std::string_view option) {
  const std::string problem =
      "expected a memory size such as 4G, 1.5GiB or 512M, got '" + std::string(text) + "'";
  double number = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (ec != std::errc() || !std::isfinite(number) || number <= 0.0)
    throw InputError(std::string(option), problem);
  std::string_view unit(end, static_cast<std::size_t>(text.data() + text.size() - end));
  if (unit.size() == 3 && unit.substr(1) == "iB") unit = unit.substr(0, 1);
  static constexpr std::string_view kUnits = "KMGT";
  double bytes = number;
  if (!unit.empty()) {
    const std::size_t power = unit.size() == 1 ? kUnits.find(unit[0]) : std::string_view::npos;
    if (power == std::string_view::npos) throw InputError(std::string(option), problem);
    bytes = std::ldexp(number, 10 * static_cast<int>(power + 1));
  }
  if (bytes < 1.0 || bytes > 0x1p63) throw InputError(std::string(option), problem);
  return static_cast<std::uint64_t>(bytes);
}

MixingMethod parseMixingMethod(const std::string& name) {
  const std::optional<MixingMethod> method = mixingMethodFromName(name);
  if (!method)
    throw InputError("--method", "expected mixing_plane or raster_convex, got '" + name + "'");
  return *method;
}

}  // namespace probeproxy::cli
