#include <feran/study/sampling.hpp>

#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

// -- the random stream: MT19937-64 (Matsumoto & Nishimura 1998; Nishimura 2000) -----

UniformStream::UniformStream(std::uint64_t seed) {
  state_[0] = seed;
  for (int i = 1; i < 312; ++i)
    state_[i] = 6364136223846793005ULL * (state_[i - 1] ^ (state_[i - 1] >> 62)) + static_cast<std::uint64_t>(i);
}

std::uint64_t UniformStream::raw() {
  constexpr std::uint64_t upper = 0xFFFFFFFF80000000ULL, lower = 0x7FFFFFFFULL;
  constexpr std::uint64_t matrix = 0xB5026F5AA96619E9ULL;
  if (index_ >= 312) {
    for (int i = 0; i < 312; ++i) {
      const std::uint64_t x = (state_[i] & upper) | (state_[(i + 1) % 312] & lower);
      state_[i] = state_[(i + 156) % 312] ^ (x >> 1) ^ ((x & 1) ? matrix : 0);
    }
    index_ = 0;
  }
  std::uint64_t y = state_[index_++];
  y ^= (y >> 29) & 0x5555555555555555ULL;
  y ^= (y << 17) & 0x71D67FFFEDA60000ULL;
  y ^= (y << 37) & 0xFFF7EEE000000000ULL;
  y ^= y >> 43;
  return y;
}

Real UniformStream::next() { return static_cast<Real>(raw() >> 11) * 0x1.0p-53; }

std::uint64_t UniformStream::below(std::uint64_t n) {
  if (n <= 1) return 0;
  const std::uint64_t limit = ~std::uint64_t(0) - (~std::uint64_t(0) % n);  // multiples of n
  for (;;) {
    const std::uint64_t x = raw();
    if (x < limit) return x % n;
  }
}

// -- full grid ------------------------------------------------------------------------

std::vector<UnitPoint> full_grid(const std::vector<Index>& levels, const std::vector<bool>& discrete) {
  Index total = 1;
  for (const Index n : levels) {
    if (n < 1) throw Error("full_grid: every dimension needs at least one level");
    if (total > Index(100'000'000) / n) throw Error("full_grid: more than 1e8 points");
    total *= n;
  }
  std::vector<UnitPoint> points(static_cast<std::size_t>(total), UnitPoint(levels.size()));
  for (Index p = 0; p < total; ++p) {
    Index rest = p;
    for (std::size_t d = levels.size(); d-- > 0;) {
      const Index n = levels[d], k = rest % n;
      rest /= n;
      Real t = 0.5;
      if (discrete[d])
        t = (static_cast<Real>(k) + 0.5) / static_cast<Real>(n);
      else if (n > 1)
        t = static_cast<Real>(k) / static_cast<Real>(n - 1);
      points[static_cast<std::size_t>(p)][d] = t;
    }
  }
  return points;
}

// -- Latin hypercube --------------------------------------------------------------------

std::vector<UnitPoint> latin_hypercube(Index n, Index dim, std::uint64_t seed) {
  if (n < 1 || dim < 1) throw Error("latin_hypercube: needs at least one point and one dimension");
  UniformStream random(seed);
  std::vector<UnitPoint> points(static_cast<std::size_t>(n), UnitPoint(static_cast<std::size_t>(dim)));
  std::vector<Index> strata(static_cast<std::size_t>(n));
  for (Index d = 0; d < dim; ++d) {
    for (Index i = 0; i < n; ++i) strata[static_cast<std::size_t>(i)] = i;
    for (Index i = n - 1; i > 0; --i)  // Fisher–Yates
      std::swap(strata[static_cast<std::size_t>(i)],
                strata[static_cast<std::size_t>(random.below(static_cast<std::uint64_t>(i + 1)))]);
    for (Index i = 0; i < n; ++i)
      points[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)] =
          (static_cast<Real>(strata[static_cast<std::size_t>(i)]) + random.next()) / static_cast<Real>(n);
  }
  return points;
}

// -- Sobol' -------------------------------------------------------------------------

namespace {

// Joe & Kuo (2008), new-joe-kuo-6.21201, dimensions 2 to 21: the degree s of the
// primitive polynomial, its coefficients a (as a binary number, without the leading
// and trailing 1) and the initial direction numbers m_1 … m_s.
struct Primitive {
  int s;
  unsigned a;
  std::array<unsigned, 7> m;
};
constexpr std::array<Primitive, max_sobol_dimensions - 1> joe_kuo{{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
    {6, 19, {1, 1, 1, 15, 7, 5}},
    {6, 22, {1, 3, 1, 15, 13, 25}},
    {6, 25, {1, 1, 5, 5, 19, 61}},
    {7, 1, {1, 3, 7, 11, 23, 15, 103}},
    {7, 4, {1, 3, 7, 13, 13, 15, 69}},
}};

constexpr int bits = 32;

// The 32 direction numbers v_1 … v_32 of one dimension (scaled by 2^32).
std::array<std::uint32_t, bits> directions(Index d) {
  std::array<std::uint32_t, bits> v{};
  if (d == 0) {  // van der Corput
    for (int k = 0; k < bits; ++k) v[static_cast<std::size_t>(k)] = std::uint32_t(1) << (bits - 1 - k);
    return v;
  }
  const auto& p = joe_kuo[static_cast<std::size_t>(d - 1)];
  for (int k = 0; k < p.s; ++k) v[static_cast<std::size_t>(k)] = p.m[static_cast<std::size_t>(k)] << (bits - 1 - k);
  for (int k = p.s; k < bits; ++k) {
    std::uint32_t x = v[static_cast<std::size_t>(k - p.s)] ^ (v[static_cast<std::size_t>(k - p.s)] >> p.s);
    for (int j = 1; j < p.s; ++j)
      if ((p.a >> (p.s - 1 - j)) & 1u) x ^= v[static_cast<std::size_t>(k - j)];
    v[static_cast<std::size_t>(k)] = x;
  }
  return v;
}

}  // namespace

std::vector<UnitPoint> sobol(Index n, Index dim, Index skip) {
  if (n < 1 || dim < 1) throw Error("sobol: needs at least one point and one dimension");
  if (dim > max_sobol_dimensions)
    throw Error(
        fmt::format("a Sobol' sequence here has at most {} dimensions, asked for {}", max_sobol_dimensions, dim));
  if (skip < 0 || n + skip > (Index(1) << 31)) throw Error("sobol: at most 2^31 points");
  std::vector<std::array<std::uint32_t, bits>> v;
  for (Index d = 0; d < dim; ++d) v.push_back(directions(d));
  std::vector<std::uint32_t> x(static_cast<std::size_t>(dim), 0);
  std::vector<UnitPoint> points;
  points.reserve(static_cast<std::size_t>(n));
  // Point i (i ≥ 1) is point i−1 with the direction numbers of the lowest zero bit
  // of i−1 added (Gray code); point 0 is the origin.
  for (Index i = 0; i < n + skip; ++i) {
    if (i > 0) {
      int c = 0;
      for (Index k = i - 1; k & 1; k >>= 1) ++c;
      for (Index d = 0; d < dim; ++d)
        x[static_cast<std::size_t>(d)] ^= v[static_cast<std::size_t>(d)][static_cast<std::size_t>(c)];
    }
    if (i < skip) continue;
    UnitPoint p(static_cast<std::size_t>(dim));
    for (Index d = 0; d < dim; ++d) p[static_cast<std::size_t>(d)] = x[static_cast<std::size_t>(d)] * 0x1.0p-32;
    points.push_back(std::move(p));
  }
  return points;
}

}  // namespace feran
