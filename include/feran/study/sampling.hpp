#pragma once
/// @file
/// Points in the unit cube [0, 1]^d for exploring a design space: a full grid, a
/// Latin hypercube and a Sobol' sequence. Each is a pure function of its arguments
/// (a seed for the random one), so that a study is reproducible on any machine.

#include <cstdint>
#include <vector>

#include <feran/core/types.hpp>

namespace feran {

using UnitPoint = std::vector<Real>;

/// The full grid: levels[i] coordinates along dimension i — 0, 1/(n−1), …, 1 for a
/// continuous variable (n ≥ 2; n = 1 gives 0.5), or the bin centres (k + ½)/n for a
/// discrete one with n values (@p discrete[i]) — every combination, the first
/// dimension varying slowest.
std::vector<UnitPoint> full_grid(const std::vector<Index>& levels, const std::vector<bool>& discrete);

/// A Latin hypercube of @p n points in @p dim dimensions (McKay, Beckman & Conover
/// 1979): each dimension cut into n equal strata, one point in each, at a uniform
/// random place within it, the strata of the dimensions paired by independent
/// random permutations. The random numbers come from a 64-bit Mersenne twister
/// seeded with @p seed, turned into uniforms and permutations by fixed formulas (not
/// the standard library's distributions, which differ between implementations).
std::vector<UnitPoint> latin_hypercube(Index n, Index dim, std::uint64_t seed);

/// The first @p n points of the Sobol' sequence in @p dim ≤ max_sobol_dimensions
/// dimensions, after skipping the first @p skip points (default 1: the origin),
/// generated in Gray-code order (Antonov & Saleev 1979) with the direction numbers
/// of Joe & Kuo (2008, "new-joe-kuo-6.21201"). Balanced for n a power of two.
std::vector<UnitPoint> sobol(Index n, Index dim, Index skip = 1);

inline constexpr Index max_sobol_dimensions = 21;

/// A 64-bit Mersenne twister's uniform numbers in [0, 1) with 53 random bits, by a
/// formula fixed here (for reproducible samples and optimiser seeds).
class UniformStream {
 public:
  explicit UniformStream(std::uint64_t seed);
  Real next();
  /// A uniform integer in [0, n), by rejection (no modulo bias).
  std::uint64_t below(std::uint64_t n);

 private:
  std::uint64_t state_[312];
  int index_ = 312;
  std::uint64_t raw();
};

}  // namespace feran
