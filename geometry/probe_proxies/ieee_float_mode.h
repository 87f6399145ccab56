#pragma once
// Embree switches its TBB worker threads to flush denormals to zero (FTZ and DAZ in MXCSR);
// the main thread keeps IEEE arithmetic. CGAL's filtered predicates assume IEEE arithmetic,
// and a probe's figures should not depend on which thread it lands on. The proxy pipeline
// runs under this guard: IEEE denormals while it lives, the thread's own mode restored after.

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace probeproxy {

class IeeeFloatMode {
 public:
#if defined(__SSE__)
  IeeeFloatMode() : saved_(_mm_getcsr()) {
    _mm_setcsr(saved_ & ~(kFlushToZero | kDenormalsAreZero));
  }
  ~IeeeFloatMode() { _mm_setcsr(saved_); }
#else
  IeeeFloatMode() = default;
#endif
  IeeeFloatMode(const IeeeFloatMode&) = delete;
  IeeeFloatMode& operator=(const IeeeFloatMode&) = delete;

 private:
#if defined(__SSE__)
  static constexpr unsigned kFlushToZero = 0x8000;
  static constexpr unsigned kDenormalsAreZero = 0x0040;
  unsigned saved_;
#endif
};

}  // namespace probeproxy
