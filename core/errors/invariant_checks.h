#pragma once
// Invariants: what the code itself guarantees, as opposed to InputError (what the user got
// wrong). Two levels, after pbrt-v4's CHECK and DCHECK:
// - PROBEPROXY_CHECK(cond): always on, for cheap checks whose failure would give a wrong
//   answer silently (a kept candidate index in range, a cube face size that matches);
// - PROBEPROXY_DCHECK(cond): Debug builds only (compiled out under NDEBUG), for checks too
//   costly for inner loops (a lookup direction of unit length, a point inside its proxy).
// A failure throws InvariantError naming the file, line and condition; the CLI reports it as an
// internal error (exit 3) and the add-on as a Python exception: the library never aborts.

#include <stdexcept>
#include <string>

namespace probeproxy {

class InvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] inline void failInvariant(const char* condition, const char* file, int line) {
  throw InvariantError(std::string(file) + ":" + std::to_string(line) +
                       ": invariant failed: " + condition);
}

}  // namespace probeproxy

#define PROBEPROXY_CHECK(condition) \
  ((condition) ? void(0) : ::probeproxy::failInvariant(#condition, __FILE__, __LINE__))

#ifdef NDEBUG
#define PROBEPROXY_DCHECK(condition) void(0)
#else
#define PROBEPROXY_DCHECK(condition) PROBEPROXY_CHECK(condition)
#endif
