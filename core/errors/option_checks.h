#pragma once
// Range checks for the options of the library's jobs. Every front end (CLI flags, the Python
// module's option dicts) hands values through unchecked and the library refuses them here, so
// a range is stated once and every front end says the same line:
//   "option tolerance_deg: -1 is not positive".
// Option names are the snake_case keys of the Python dicts, the CLI's flags without the dashes.

#include "core/errors/input_error.h"

#include <sstream>
#include <string>
#include <string_view>

namespace probeproxy {

namespace detail {
template <typename T>
[[noreturn]] void refuseOption(std::string_view name, T value, std::string_view problem) {
  std::ostringstream text;
  text << value << " " << problem;
  throw InputError("option " + std::string(name), text.str());
}
}  // namespace detail

// Throws InputError unless low <= value <= high (NaN fails).
template <typename T>
void requireInRange(std::string_view name, T value, T low, T high) {
  if (value >= low && value <= high) return;
  std::ostringstream range;
  range << "is outside [" << low << ", " << high << "]";
  detail::refuseOption(name, value, range.str());
}

template <typename T>
void requirePositive(std::string_view name, T value) {
  if (!(value > T(0))) detail::refuseOption(name, value, "is not positive");
}

template <typename T>
void requireNonNegative(std::string_view name, T value) {
  if (!(value >= T(0))) detail::refuseOption(name, value, "is negative");
}

}  // namespace probeproxy
