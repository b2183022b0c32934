// The samplers against their defining properties: the random stream equals the
// standard's MT19937-64, a Latin hypercube has one point per stratum in every
// dimension, Sobol' points are (0, m, 1)-nets in each dimension and a (0, m, 2)-net
// in the first two, and a grid visits every combination once.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include <feran/core/error.hpp>
#include <feran/study/sampling.hpp>

namespace feran::test_sampling {
namespace {

TEST(UniformStream, IsTheStandardMersenneTwister) {
  // std::mt19937_64 is specified bit for bit (C++ [rand.predef]); ours must equal it,
  // so that a study's samples do not depend on the standard library.
  for (const std::uint64_t seed : {1ULL, 42ULL, 5489ULL, 0xFFFFFFFFFFFFULL}) {
    std::mt19937_64 reference(seed);
    UniformStream ours(seed);
    for (int i = 0; i < 2000; ++i)
      ASSERT_EQ(ours.next(), static_cast<Real>(reference() >> 11) * 0x1.0p-53) << "seed " << seed << ", draw " << i;
  }
  // The standard's check value: the 10000th output of the default seed.
  std::mt19937_64 reference;
  UniformStream ours(5489);
  for (int i = 0; i < 9999; ++i) (void)ours.next();
  reference.discard(9999);
  EXPECT_EQ(reference(), 9981545732273789042ULL);
}

TEST(UniformStream, BelowIsUniformWithoutBias) {
  // 60 000 draws in [0, 3): each count within 4 standard deviations (√(n p (1−p)) = 115).
  UniformStream s(7);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 60000; ++i) ++counts[s.below(3)];
  for (const int c : counts) EXPECT_NEAR(c, 20000, 4 * 115.5);
}

TEST(LatinHypercube, OnePointPerStratumInEveryDimension) {
  const Index n = 37, dim = 5;
  const auto points = latin_hypercube(n, dim, 123);
  ASSERT_EQ(points.size(), static_cast<std::size_t>(n));
  for (Index d = 0; d < dim; ++d) {
    std::set<Index> strata;
    for (const auto& p : points) {
      ASSERT_GE(p[d], 0.0);
      ASSERT_LT(p[d], 1.0);
      strata.insert(static_cast<Index>(std::floor(p[d] * n)));
    }
    EXPECT_EQ(strata.size(), static_cast<std::size_t>(n)) << "dimension " << d;
  }
  // Reproducible from the seed, different for another.
  EXPECT_EQ(latin_hypercube(n, dim, 123), points);
  EXPECT_NE(latin_hypercube(n, dim, 124), points);
}

TEST(Sobol, FirstPointsAreTheKnownOnes) {
  // Dimensions 1 and 2 of the Sobol' sequence after the origin (Bratley & Fox 1988):
  // (1/2, 1/2), (3/4, 1/4), (1/4, 3/4), (3/8, 3/8), (7/8, 7/8).
  const auto p = sobol(5, 2);
  const Real expected[5][2] = {{0.5, 0.5}, {0.75, 0.25}, {0.25, 0.75}, {0.375, 0.375}, {0.875, 0.875}};
  for (int i = 0; i < 5; ++i)
    for (int d = 0; d < 2; ++d) EXPECT_EQ(p[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)], expected[i][d]);
}

TEST(Sobol, EveryDimensionIsANetAndTheFirstTwoATwoDimensionalOne) {
  // With the origin included (skip 0), the first 2^m points of each dimension fall one
  // into each interval [k/2^m, (k+1)/2^m): the direction numbers are valid (odd m_i
  // below 2^i) and the polynomials primitive. The first two dimensions together put
  // one point in each elementary box of area 2^-m ((0, m, 2)-net, Sobol' 1967).
  const int m = 10;
  const Index n = Index(1) << m;
  const auto p = sobol(n, max_sobol_dimensions, 0);
  for (Index d = 0; d < max_sobol_dimensions; ++d) {
    std::set<Index> cells;
    for (const auto& x : p) cells.insert(static_cast<Index>(x[d] * n));
    EXPECT_EQ(cells.size(), static_cast<std::size_t>(n)) << "dimension " << d + 1;
  }
  for (int a = 0; a <= m; ++a) {
    std::set<std::pair<Index, Index>> boxes;
    for (const auto& x : p)
      boxes.insert({static_cast<Index>(x[0] * std::ldexp(1.0, a)), static_cast<Index>(x[1] * std::ldexp(1.0, m - a))});
    EXPECT_EQ(boxes.size(), static_cast<std::size_t>(n)) << "boxes of 2^-" << a << " by 2^-" << m - a;
  }
}

TEST(Sobol, RefusesMoreDimensionsThanItHasDirectionNumbers) { EXPECT_THROW(sobol(4, max_sobol_dimensions + 1), Error); }

TEST(FullGrid, EveryCombinationOnceFirstDimensionSlowest) {
  const auto g = full_grid({3, 2}, {false, true});
  ASSERT_EQ(g.size(), 6u);
  const std::vector<UnitPoint> expected{{0, 0.25}, {0, 0.75}, {0.5, 0.25}, {0.5, 0.75}, {1, 0.25}, {1, 0.75}};
  EXPECT_EQ(g, expected);
  EXPECT_EQ(full_grid({1}, {false}), std::vector<UnitPoint>{{0.5}});
}

}  // namespace
}  // namespace feran::test_sampling
