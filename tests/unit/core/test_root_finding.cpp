#include <gtest/gtest.h>

#include <cmath>

#include <feran/core/root_finding.hpp>

namespace feran::test_root_finding {
namespace {

TEST(BrentRoot, FindsCosineRootToTolerance) {
  int calls = 0;
  auto f = [&](Real x) {
    ++calls;
    return std::cos(x);
  };
  const RootResult r = brent_root(f, 1.0, 2.0, std::cos(1.0), std::cos(2.0), 1e-12);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.x, pi / 2, 1e-12);  // the requested tolerance
  EXPECT_EQ(r.evaluations, calls);
  EXPECT_LT(calls, 15);  // superlinear: bisection alone would need ~40
}

TEST(BrentRoot, HandlesRootAtBracketEnd) {
  auto f = [](Real x) { return x * (x - 1.0) * (x + 1.0); };
  EXPECT_EQ(brent_root(f, 0.0, 0.5, 0.0, f(0.5), 1e-12).x, 0.0);
  const RootResult r = brent_root(f, 0.5, 2.0, f(0.5), f(2.0), 1e-12);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.x, 1.0, 1e-12);
}

TEST(BrentRoot, ReportsAMissingBracket) {
  auto f = [](Real x) { return x * x + 1.0; };
  EXPECT_FALSE(brent_root(f, -1.0, 1.0, 2.0, 2.0, 1e-12).converged);
}

TEST(BrentRoot, StopsAtTheEvaluationLimit) {
  auto f = [](Real x) { return x - 1.0 / 3.0; };
  const RootResult r = brent_root(f, 0.0, 1.0, f(0.0), f(1.0), 0.0, 2);
  EXPECT_LE(r.evaluations, 2);
}

}  // namespace
}  // namespace feran::test_root_finding
