#pragma once
// A fit that its input cannot give: too few points, points that span no volume (one line, one
// plane), planes that bound no volume, an interior point that is not inside. Not a bug and not
// a bad file: a probe that sees only a floor has no hull. Callers catch it and fall back to
// another proxy kind; the message says what was wrong, with the numbers, in one line.

#include <stdexcept>

namespace probeproxy {

class FitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace probeproxy
