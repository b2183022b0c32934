#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include <feran/core/assignment.hpp>

namespace feran::test_assignment {
namespace {

Real total(const Matrix& c, const std::vector<Index>& a) {
  Real s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += c(static_cast<Index>(i), a[i]);
  return s;
}

TEST(Assignment, SmallKnownCase) {
  Matrix c(3, 3);
  c << 4, 1, 3,  //
      2, 0, 5,   //
      3, 2, 2;
  // Optimum 1 + 2 + 2 = 5 (rows → columns 1, 0, 2).
  const auto a = optimal_assignment(c);
  EXPECT_EQ(a, (std::vector<Index>{1, 0, 2}));
}

// Against exhaustive search over all permutations of random square and rectangular
// problems: the costs must agree exactly (same sums of the same numbers).
TEST(Assignment, MatchesBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Index rows = 1 + trial % 5, cols = rows + trial % 3;
    Matrix c(rows, cols);
    for (Index i = 0; i < rows; ++i)
      for (Index j = 0; j < cols; ++j) c(i, j) = u(rng);
    const auto a = optimal_assignment(c);
    std::vector<Index> cols_used(a);
    std::sort(cols_used.begin(), cols_used.end());
    EXPECT_EQ(std::adjacent_find(cols_used.begin(), cols_used.end()), cols_used.end());
    std::vector<Index> perm(static_cast<std::size_t>(cols));
    std::iota(perm.begin(), perm.end(), 0);
    Real best = 1e300;
    do {
      best = std::min(best, total(c, std::vector<Index>(perm.begin(), perm.begin() + rows)));
    } while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_NEAR(total(c, a), best, 1e-12);
  }
}

TEST(Assignment, RejectsMoreRowsThanColumns) {
  EXPECT_THROW(optimal_assignment(Matrix::Zero(3, 2)), std::invalid_argument);
}

}  // namespace
}  // namespace feran::test_assignment
