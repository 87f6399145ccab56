// The two levels of invariant checks: CHECK always throws on a broken invariant, DCHECK only in
// Debug builds (compiled out under NDEBUG, so it costs nothing in Release inner loops).

#include "core/errors/invariant_checks.h"

#include <gtest/gtest.h>

#include <string>

namespace probeproxy {
namespace {

TEST(InvariantChecks, CheckThrowsNamingTheConditionAndTheLine) {
  try {
    PROBEPROXY_CHECK(1 + 1 == 3);
    FAIL() << "no throw";
  } catch (const InvariantError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("invariant_checks_test.cpp:"), std::string::npos) << what;
    EXPECT_NE(what.find("invariant failed: 1 + 1 == 3"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(PROBEPROXY_CHECK(1 + 1 == 2));
}

TEST(InvariantChecks, DebugCheckRunsOnlyWithoutNdebug) {
  int evaluated = 0;
  const auto broken = [&] {
    ++evaluated;
    return false;
  };
  (void)broken;  // unused where DCHECK compiles out
#ifdef NDEBUG
  EXPECT_NO_THROW(PROBEPROXY_DCHECK(broken()));
  EXPECT_EQ(evaluated, 0);  // not even evaluated
#else
  EXPECT_THROW(PROBEPROXY_DCHECK(broken()), InvariantError);
  EXPECT_EQ(evaluated, 1);
#endif
}

}  // namespace
}  // namespace probeproxy
