// Instructions per lookup under callgrind (plugin/cost/instructions_per_lookup.h): counts are
// deterministic, so a range can be asserted where a time could not.

#include "plugin/cost/instructions_per_lookup.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

TEST(InstructionsPerLookup, AabbScalarInSaneRangeAndBatchedLower) {
  const std::optional<double> scalar = instructionsPerLookup("aabb", LookupPath::Scalar, 1024);
  if (!scalar) GTEST_SKIP() << "valgrind is not on PATH";
  const std::optional<double> batched = instructionsPerLookup("aabb", LookupPath::Batched, 1024);
  ASSERT_TRUE(batched);
  // The scalar path: the seed port (~100), its shared miss/finish step, the method dispatch
  // and the caller's loop; far below the thousands a per-call allocation would cost.
  EXPECT_GT(*scalar, 10.0);
  EXPECT_LT(*scalar, 400.0);
  EXPECT_GT(*batched, 2.0);
  EXPECT_LT(*batched, *scalar / 2.0);
}

TEST(InstructionsPerLookup, SameCountEveryRun) {
  const std::optional<double> a = instructionsPerLookup("convex_6", LookupPath::Batched, 256);
  if (!a) GTEST_SKIP() << "valgrind is not on PATH";
  EXPECT_EQ(a, instructionsPerLookup("convex_6", LookupPath::Batched, 256));
}

TEST(InstructionsPerLookup, OneRunForManyWorkloadsCountsEachAlone) {
  const std::vector<std::string> workloads = {"aabb", "convex_6", "convex_20", "infinite"};
  const std::vector<std::optional<double>> many =
      instructionsPerLookup(workloads, LookupPath::Batched, 256);
  ASSERT_EQ(many.size(), workloads.size());
  if (!many.front()) GTEST_SKIP() << "valgrind is not on PATH";
  for (std::size_t i = 0; i < workloads.size(); ++i)
    EXPECT_EQ(many[i], instructionsPerLookup(workloads[i], LookupPath::Batched, 256))
        << workloads[i];
  EXPECT_THROW(instructionsPerLookup(std::vector<std::string>{"aabb", "cone"}, LookupPath::Batched),
               std::invalid_argument);
}

TEST(InstructionsPerLookup, UnknownWorkloadAndMissingDriverAreErrors) {
  EXPECT_THROW(instructionsPerLookup("cone", LookupPath::Scalar), std::invalid_argument);
  EXPECT_THROW(instructionsPerLookup("convex_3", LookupPath::Scalar), std::invalid_argument);
  if (!instructionsPerLookup("infinite", LookupPath::Scalar, 16)) GTEST_SKIP();
  EXPECT_THROW(instructionsPerLookup("aabb", LookupPath::Scalar, 16, "/nonexistent/driver"),
               std::runtime_error);
}

}  // namespace
}  // namespace probeproxy
