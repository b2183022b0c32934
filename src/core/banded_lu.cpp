#include <feran/core/banded_lu.hpp>

#include <algorithm>
#include <array>
#include <type_traits>
#include <utility>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <feran/core/components.hpp>
#include <feran/core/error.hpp>
#include <feran/core/ordering.hpp>

namespace feran {

Index BandedLU::half_bandwidth(const SparseMatrix& pattern) {
  Index b = 0;
  for (Index k = 0; k < pattern.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(pattern, k); it; ++it) b = std::max(b, std::abs(it.row() - it.col()));
  return b;
}

void BandedLU::resize(Index n, Index b) {
  n_ = n;
  b_ = std::min(b, std::max<Index>(n - 1, 0));
  blocks_ = {Block{n_, b_, 0, 0}};
  block_of_.clear();
  local_of_.clear();
  order_.clear();
  a_.assign(static_cast<std::size_t>(n_ * (2 * b_ + 1)), 0.0);
}

bool BandedLU::partition(Index n, const std::vector<const SparseMatrix*>& patterns, Index largest_bandwidth) {
  if (n == 0) {
    resize(0, 0);
    return true;
  }
  for (const SparseMatrix* S : patterns)
    if (S->rows() != n || S->cols() != n) throw Error("BandedLU::partition: a matrix of another size");
  // Each component keeps the unknowns' order.
  block_of_ = connected_components(n, patterns, false);
  local_of_.assign(static_cast<std::size_t>(n), 0);
  std::vector<Index> count;
  for (Index i = 0; i < n; ++i) {
    const auto c = static_cast<std::size_t>(block_of_[static_cast<std::size_t>(i)]);
    if (c == count.size()) count.push_back(0);
    local_of_[static_cast<std::size_t>(i)] = count[c]++;
  }
  // Each component's half-bandwidth in its numbering local_of_.
  const auto bandwidths = [&] {
    std::vector<Index> bandwidth(count.size(), 0);
    for (const SparseMatrix* S : patterns)
      for (Index k = 0; k < S->outerSize(); ++k)
        for (SparseMatrix::InnerIterator it(*S, k); it; ++it) {
          Index& b = bandwidth[static_cast<std::size_t>(block_of_[static_cast<std::size_t>(it.row())])];
          b = std::max(b, std::abs(local_of_[static_cast<std::size_t>(it.row())] -
                                   local_of_[static_cast<std::size_t>(it.col())]));
        }
    return bandwidth;
  };
  std::vector<Index> bandwidth = bandwidths();
  // A component too wide in the unknowns' order: the reverse Cuthill–McKee order
  // within it (the order numbers each component in one run).
  bool reordered = false;
  if (*std::max_element(bandwidth.begin(), bandwidth.end()) > largest_bandwidth) {
    std::vector<Index> next(count.size(), 0);
    for (const Index i : reverse_cuthill_mckee(pattern_graph(n, patterns))) {
      const auto c = static_cast<std::size_t>(block_of_[static_cast<std::size_t>(i)]);
      if (bandwidth[c] > largest_bandwidth) local_of_[static_cast<std::size_t>(i)] = next[c]++;
    }
    bandwidth = bandwidths();
    reordered = true;
  }
  if (*std::max_element(bandwidth.begin(), bandwidth.end()) > largest_bandwidth) {
    resize(0, 0);
    return false;
  }
  n_ = n;
  b_ = 0;
  blocks_.clear();
  Index offset = 0, first = 0;
  for (std::size_t c = 0; c < count.size(); ++c) {
    blocks_.push_back(Block{count[c], bandwidth[c], offset, first});
    offset += count[c] * (2 * bandwidth[c] + 1);
    first += count[c];
    b_ = std::max(b_, bandwidth[c]);
  }
  order_.assign(static_cast<std::size_t>(n), 0);
  for (Index i = 0; i < n; ++i)
    order_[static_cast<std::size_t>(blocks_[static_cast<std::size_t>(block_of_[static_cast<std::size_t>(i)])].first +
                                    local_of_[static_cast<std::size_t>(i)])] = i;
  if (blocks_.size() == 1 && !reordered) {  // one component in the unknowns' order: no gathering
    block_of_.clear();
    local_of_.clear();
    order_.clear();
  }
  a_.assign(static_cast<std::size_t>(offset), 0.0);
  work_.assign(static_cast<std::size_t>(n), 0.0);
  return true;
}

Index BandedLU::index(Index i, Index j) const {
  if (block_of_.empty()) return std::abs(i - j) > b_ ? -1 : j * (2 * b_ + 1) + (i - j + b_);
  const Index c = block_of_[static_cast<std::size_t>(i)];
  if (block_of_[static_cast<std::size_t>(j)] != c) return -1;
  const Block& blk = blocks_[static_cast<std::size_t>(c)];
  const Index li = local_of_[static_cast<std::size_t>(i)], lj = local_of_[static_cast<std::size_t>(j)];
  return std::abs(li - lj) > blk.b ? -1 : blk.offset + lj * (2 * blk.b + 1) + (li - lj + blk.b);
}

void BandedLU::set_zero() { std::fill(a_.begin(), a_.end(), 0.0); }

void BandedLU::set_combination(const std::vector<Real>& A, Real c, const std::vector<Real>& B) {
  if (A.size() != a_.size() || B.size() != a_.size()) throw Error("BandedLU::set_combination: values of another band");
  const std::size_t m = a_.size();
  Real* out = a_.data();
  const Real* a = A.data();
  const Real* b = B.data();
  for (std::size_t i = 0; i < m; ++i) out[i] = a[i] + c * b[i];
}

void BandedLU::add(Real c, const SparseMatrix& S) {
  if (S.rows() != n_ || S.cols() != n_) throw Error("BandedLU::add: a matrix of another size");
  for (Index k = 0; k < S.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(S, k); it; ++it) {
      const Index at = index(it.row(), it.col());
      if (at < 0) throw Error("BandedLU::add: an entry outside the band");
      a_[static_cast<std::size_t>(at)] += c * it.value();
    }
}

std::vector<Index> BandedLU::positions(const SparseMatrix& S) const {
  if (S.rows() != n_ || S.cols() != n_ || !S.isCompressed())
    throw Error("BandedLU::positions: a matrix of another size, or not compressed");
  std::vector<Index> out;
  out.reserve(static_cast<std::size_t>(S.nonZeros()));
  for (Index k = 0; k < S.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(S, k); it; ++it) {
      const Index at = index(it.row(), it.col());
      if (at < 0) throw Error("BandedLU::positions: an entry outside the band");
      out.push_back(at);
    }
  return out;
}

void BandedLU::add(Real c, const SparseMatrix& S, const std::vector<Index>& positions) {
  const Real* v = S.valuePtr();
  Real* a = a_.data();
  const std::size_t n = positions.size();
  for (std::size_t e = 0; e < n; ++e) a[positions[e]] += c * v[e];
}

namespace {

constexpr Real smallest_pivot = 1e-10;

// Column k of the elimination, m rows below the diagonal in the band (m ≤ b):
// L(k + 1 … k + m, k) scaled, the trailing block updated. False on a small pivot.
inline bool eliminate(Real* a, Index ld, Index b, Index k, Index m, Real* inverse) {
  Real* ck = a + k * ld;
  const Real p = ck[b];
  Real largest = std::abs(p);
  for (Index i = 1; i <= m; ++i) largest = std::max(largest, std::abs(ck[b + i]));
  if (!std::isfinite(p) || !(std::abs(p) > smallest_pivot * largest)) return false;
  const Real r = 1.0 / p;
  inverse[k] = r;
  Real* l = ck + b + 1;
  for (Index i = 0; i < m; ++i) l[i] *= r;
  for (Index j = 1; j <= m; ++j) {
    Real* d = a + (k + j) * ld + (b - j + 1);
    const Real u = d[-1];  // U(k, k + j); the band is not full (a rotor's: about half)
    if (u == 0.0) continue;
    for (Index i = 0; i < m; ++i) d[i] -= l[i] * u;
  }
  return true;
}

// The same with the half-bandwidth B known when compiling, for the columns with B
// rows below the diagonal: the loops unrolled.
template <int B>
bool factorize_fixed(Real* a, Index n, Real* inverse) {
  constexpr Index ld = 2 * B + 1;
  Index k = 0;
  for (; k + B < n; ++k) {
    Real* ck = a + k * ld;
    const Real p = ck[B];
    Real largest = std::abs(p);
    for (int i = 1; i <= B; ++i) largest = std::max(largest, std::abs(ck[B + i]));
    if (!std::isfinite(p) || !(std::abs(p) > smallest_pivot * largest)) return false;
    const Real r = 1.0 / p;
    inverse[k] = r;
    std::array<Real, B> l;
    for (int i = 0; i < B; ++i) l[i] = ck[B + 1 + i] *= r;
    for (int j = 1; j <= B; ++j) {
      Real* d = a + (k + j) * ld + (B - j + 1);
      const Real u = d[-1];
      if (u == 0.0) continue;
      for (int i = 0; i < B; ++i) d[i] -= l[i] * u;
    }
  }
  for (; k < n; ++k)
    if (!eliminate(a, ld, B, k, n - 1 - k, inverse)) return false;
  return true;
}

bool factorize_any(Real* a, Index n, Index b, Real* inverse) {
  const Index ld = 2 * b + 1;
  for (Index k = 0; k < n; ++k)
    if (!eliminate(a, ld, b, k, std::min(b, n - 1 - k), inverse)) return false;
  return true;
}

// Forward and back substitution. A column sweep (y(k+1 … k+b) −= L·y(k)) stalls on
// each column reading what the previous one just wrote; here the corrections still
// owed to the next B unknowns are carried in a small array the compiler keeps in
// registers, so that one column's critical path is a subtraction and a product
// (at 1210 DOF, b = 10: 9 µs against 20 µs). S: the stride between a factor's
// entries (1; the lanes' count for one lane of factorize_lanes()).
template <int B, int S>
void substitute_fixed(const Real* a, const Real* inverse, Index n, Real* y) {
  constexpr Index ld = 2 * B + 1;
  std::array<Real, B> owed{};
  Index k = 0;
  for (; k + B < n; ++k) {
    const Real yk = y[k] - owed[0];
    y[k] = yk;
    const Real* l = a + (k * ld + B + 1) * S;
    for (Index i = 0; i < B - 1; ++i) owed[i] = owed[i + 1] + l[i * S] * yk;
    owed[B - 1] = l[Index{B - 1} * S] * yk;
  }
  for (int i = 0; i < B && k + i < n; ++i) y[k + i] -= owed[i];
  for (; k < n; ++k) {
    const Real* l = a + (k * ld + B + 1) * S;
    const Real yk = y[k];
    for (Index i = 0; i < n - 1 - k; ++i) y[k + 1 + i] -= l[i * S] * yk;
  }
  owed.fill(0.0);
  k = n - 1;
  for (; k >= B; --k) {
    const Real* ck = a + k * ld * S;
    const Real xk = (y[k] - owed[0]) * inverse[k * S];
    y[k] = xk;
    for (Index i = 0; i < B - 1; ++i) owed[i] = owed[i + 1] + ck[(B - 1 - i) * S] * xk;
    owed[B - 1] = ck[0] * xk;
  }
  for (int i = 0; i < B && k - i >= 0; ++i) y[k - i] -= owed[i];
  for (; k >= 0; --k) {
    const Real* ck = a + k * ld * S;
    const Real xk = y[k] * inverse[k * S];
    y[k] = xk;
    for (Index i = 1; i <= k; ++i) y[k - i] -= ck[(B - i) * S] * xk;
  }
}

void substitute_any(const Real* a, const Real* inverse, Index n, Index b, Index S, Real* y) {
  const Index ld = 2 * b + 1;
  for (Index k = 0; k < n; ++k) {  // L·y = b, unit diagonal
    const Real* l = a + (k * ld + b + 1) * S;
    const Index m = std::min(b, n - 1 - k);
    const Real yk = y[k];
    for (Index i = 0; i < m; ++i) y[k + 1 + i] -= l[i * S] * yk;
  }
  for (Index k = n - 1; k >= 0; --k) {  // U·x = y
    const Real* ck = a + k * ld * S;
    y[k] *= inverse[k * S];
    const Index m = std::min(b, k);
    const Real xk = y[k];
    for (Index i = 1; i <= m; ++i) y[k - i] -= ck[(b - i) * S] * xk;
  }
}

// Several matrices of one pattern factorised at once, lane L of each vector holding
// matrix L's entry (GCC's vector extension: AVX2 registers where the build has them,
// pairs of SSE2 ones otherwise). Each lane does exactly the arithmetic of
// factorize_fixed(); the lanes share its instructions, so that the chain through the
// pivots (a division, the multipliers, the next column's update: latency, not
// throughput, bounds one matrix) is paid once for all of them.
using LaneVector = Real __attribute__((vector_size(BandedLU::lanes * sizeof(Real))));
using LaneBits = std::int64_t __attribute__((vector_size(BandedLU::lanes * sizeof(Real))));
static_assert(BandedLU::lanes == 4, "the lanes' vectors are spelt out with four entries");

inline LaneVector lane_abs(LaneVector x) {
  return reinterpret_cast<LaneVector>(reinterpret_cast<LaneBits>(x) & std::numeric_limits<std::int64_t>::max());
}

// All ones in the lanes whose pivot p is finite and not below smallest_pivot of its
// column's largest entry (kept as a vector across columns: reading the lanes out at
// each column cost as much as the column's arithmetic).
inline LaneBits good_pivots(LaneVector p, LaneVector largest) {
  const LaneVector ap = lane_abs(p);
  return (ap > smallest_pivot * largest) & (ap <= std::numeric_limits<Real>::max());
}

// A bit for each lane that is all ones in @p good.
inline unsigned lane_bits(LaneBits good) {
  unsigned bits = 0;
  for (int l = 0; l < BandedLU::lanes; ++l)
    if (good[l] != 0) bits |= 1u << l;
  return bits;
}

inline bool all_zero(LaneVector u) {
  const LaneBits z = reinterpret_cast<LaneBits>(u) & std::numeric_limits<std::int64_t>::max();
  std::int64_t any = 0;
  for (int l = 0; l < BandedLU::lanes; ++l) any |= z[l];
  return any == 0;
}

// The lanes' matrices A + c·B (+ additions) are set a column at a time, just before
// the elimination first reaches the column, so that it is written once and then
// updated while in cache: at 1210 DOF (b = 7 and twice 1) 5.5 µs a matrix, where
// setting the four first and then factorising took 6.8 µs, and one matrix alone
// (factorize()) 17 µs. (Left-looking, each column finished in registers before the
// next, measured 6.1–7.3 µs: its column's updates form one chain.)
struct LaneSource {
  const Real* A;
  const Real* B;
  LaneVector c;
  const BandedLU::LaneAddition* add;  // sorted by position; consumed as columns are set
  const BandedLU::LaneAddition* add_end;
  Index offset;  // of the block in the band's storage (the additions' positions count from 0)

  // Column j's ld entries at a + j·ld.
  void set_column(LaneVector* a, Index ld, Index j) { column(a + j * ld, ld, j); }
  // Column j's ld entries into @p col.
  void column(LaneVector* col, Index ld, Index j) {
    const Real* aj = A + j * ld;
    const Real* bj = B + j * ld;
    for (Index i = 0; i < ld; ++i) col[i] = aj[i] + c * bj[i];
    const Index first = offset + j * ld;
    for (; add != add_end && add->position < first + ld; ++add) {
      const LaneVector v = {add->value[0], add->value[1], add->value[2], add->value[3]};
      col[add->position - first] += v;
    }
  }
};

// Column j's last steps: the pivot judged, its reciprocal kept, L scaled (m rows).
inline LaneBits finish_lane_column(LaneVector* col, Index b, Index m, LaneVector& inverse) {
  const LaneVector p = col[b];
  LaneVector largest = lane_abs(p);
  for (Index i = 1; i <= m; ++i) {
    const LaneVector e = lane_abs(col[b + i]);
    largest = largest > e ? largest : e;
  }
  const LaneVector r = 1.0 / p;
  inverse = r;
  for (Index i = 1; i <= m; ++i) col[b + i] *= r;
  return good_pivots(p, largest);
}

// Column j (in place in @p a) brought up to date by the finished columns before it,
// at any half-bandwidth and near the band's ends.
inline void update_lane_column(LaneVector* a, Index n, Index b, Index j, LaneVector* col) {
  const Index ld = 2 * b + 1;
  for (Index k = std::max<Index>(0, j - b); k < j; ++k) {
    const LaneVector u = col[k - j + b];
    if (all_zero(u)) continue;
    const LaneVector* l = a + k * ld + b + 1;
    const Index m = std::min(b, n - 1 - k);
    for (Index i = 0; i < m; ++i) col[k + 1 + i - j + b] -= l[i] * u;
  }
}

// In place at the band's ends, where columns have fewer updates or rows.
inline LaneBits factorize_lane_column(LaneVector* a, Index n, Index b, Index j, LaneVector* inverse,
                                      LaneSource& source) {
  LaneVector* col = a + j * (2 * b + 1);
  source.column(col, 2 * b + 1, j);
  update_lane_column(a, n, b, j, col);
  return finish_lane_column(col, b, std::min(b, n - 1 - j), inverse[j]);
}

// Right-looking, as factorize_fixed(): column k's multipliers update the trailing
// block at once; column k + B is set just before step k first reaches it.
template <int B>
LaneBits factorize_lanes_fixed(LaneVector* a, Index n, LaneVector* inverse, LaneSource& source) {
  constexpr Index ld = 2 * B + 1;
  LaneBits good = ~LaneBits{};
  if (n <= B) {
    for (Index j = 0; j < n; ++j) good &= factorize_lane_column(a, n, B, j, inverse, source);
    return good;
  }
  for (Index j = 0; j <= B; ++j) source.set_column(a, ld, j);
  Index k = 0;
  for (; k + B < n; ++k) {
    if (k > 0) source.set_column(a, ld, k + B);
    LaneVector* ck = a + k * ld;
    good &= finish_lane_column(ck, B, B, inverse[k]);
    LaneVector l[B];  // in registers: the stores below cannot change them
    for (int i = 0; i < B; ++i) l[i] = ck[B + 1 + i];
    for (int j = 1; j <= B; ++j) {
      LaneVector* d = a + (k + j) * ld + (B - j + 1);
      const LaneVector u = d[-1];
      if (all_zero(u)) continue;
      for (int i = 0; i < B; ++i) d[i] -= l[i] * u;
    }
  }
  for (; k < n; ++k) {
    LaneVector* ck = a + k * ld;
    const Index m = n - 1 - k;
    good &= finish_lane_column(ck, B, m, inverse[k]);
    for (Index j = 1; j <= m; ++j) {
      LaneVector* d = a + (k + j) * ld + (B - j + 1);
      const LaneVector u = d[-1];
      for (Index i = 0; i < m; ++i) d[i] -= ck[B + 1 + i] * u;
    }
  }
  return good;
}

LaneBits factorize_lanes_any(LaneVector* a, Index n, Index b, LaneVector* inverse, LaneSource& source) {
  LaneBits good = ~LaneBits{};
  for (Index j = 0; j < n; ++j) good &= factorize_lane_column(a, n, b, j, inverse, source);
  return good;
}

// Kernels for half-bandwidths 1 … 16 (a rotor's are 4 … 12), the general ones beyond.
constexpr int fixed_bands = 16;

template <std::size_t... I>
constexpr auto factor_kernels(std::index_sequence<I...>) {
  return std::array<bool (*)(Real*, Index, Real*), sizeof...(I)>{&factorize_fixed<static_cast<int>(I) + 1>...};
}
template <std::size_t... I>
constexpr auto lane_factor_kernels(std::index_sequence<I...>) {
  return std::array<LaneBits (*)(LaneVector*, Index, LaneVector*, LaneSource&), sizeof...(I)>{
      &factorize_lanes_fixed<static_cast<int>(I) + 1>...};
}
template <int S, std::size_t... I>
constexpr auto substitute_kernels(std::index_sequence<I...>) {
  return std::array<void (*)(const Real*, const Real*, Index, Real*), sizeof...(I)>{
      &substitute_fixed<static_cast<int>(I) + 1, S>...};
}
constexpr auto factor_fixed = factor_kernels(std::make_index_sequence<fixed_bands>{});
constexpr auto lane_factor_fixed = lane_factor_kernels(std::make_index_sequence<fixed_bands>{});
constexpr auto substitute_fixed_kernels = substitute_kernels<1>(std::make_index_sequence<fixed_bands>{});
constexpr auto substitute_lane_kernels = substitute_kernels<BandedLU::lanes>(std::make_index_sequence<fixed_bands>{});

}  // namespace

bool BandedLU::factorize() {
  inverse_.resize(static_cast<std::size_t>(n_));
  for (const Block& blk : blocks_) {
    Real* a = a_.data() + blk.offset;
    Real* inverse = inverse_.data() + blk.first;
    const bool ok = blk.b >= 1 && blk.b <= fixed_bands
                        ? factor_fixed[static_cast<std::size_t>(blk.b - 1)](a, blk.n, inverse)
                        : factorize_any(a, blk.n, blk.b, inverse);
    if (!ok) return false;
  }
  return true;
}

void BandedLU::solve_in_place(Vector& x) const { substitute(a_.data(), inverse_.data(), 1, x); }

namespace {

// The lanes' storage aligned to a vector (it holds a vector's reals more than the
// values need).
template <class Storage>
auto aligned_lanes(Storage& storage) {
  const auto address = reinterpret_cast<std::uintptr_t>(storage.data());
  const std::uintptr_t align = sizeof(LaneVector);
  auto* first = storage.data() + ((align - address % align) % align) / sizeof(Real);
  if constexpr (std::is_const_v<Storage>)
    return reinterpret_cast<const LaneVector*>(first);
  else
    return reinterpret_cast<LaneVector*>(first);
}

}  // namespace

unsigned BandedLU::factorize_lanes(const std::vector<Real>& A, const std::array<Real, lanes>& c,
                                   const std::vector<Real>& B, const std::vector<LaneAddition>& additions) {
  if (A.size() != a_.size() || B.size() != a_.size()) throw Error("BandedLU::factorize_lanes: values of another band");
  for (std::size_t e = 0; e < additions.size(); ++e)
    if (additions[e].position < 0 || additions[e].position >= static_cast<Index>(a_.size()) ||
        (e > 0 && additions[e].position < additions[e - 1].position))
      throw Error("BandedLU::factorize_lanes: additions outside the band or not sorted by position");
  lane_values_.resize((a_.size() + 1) * lanes);
  lane_inverse_.resize(static_cast<std::size_t>(n_ + 1) * lanes);
  LaneVector* values = aligned_lanes(lane_values_);
  LaneVector* inverse = aligned_lanes(lane_inverse_);
  LaneSource source{
      A.data(), B.data(), LaneVector{c[0], c[1], c[2], c[3]}, additions.data(), additions.data() + additions.size(), 0};
  LaneBits good = ~LaneBits{};
  for (const Block& blk : blocks_) {
    source.A = A.data() + blk.offset;
    source.B = B.data() + blk.offset;
    source.offset = blk.offset;
    LaneVector* a = values + blk.offset;
    LaneVector* inv = inverse + blk.first;
    good &= blk.b >= 1 && blk.b <= fixed_bands
                ? lane_factor_fixed[static_cast<std::size_t>(blk.b - 1)](a, blk.n, inv, source)
                : factorize_lanes_any(a, blk.n, blk.b, inv, source);
  }
  return lane_bits(good);
}

void BandedLU::solve_in_place(Vector& x, int lane) const {
  substitute(reinterpret_cast<const Real*>(aligned_lanes(lane_values_)) + lane,
             reinterpret_cast<const Real*>(aligned_lanes(lane_inverse_)) + lane, lanes, x);
}

void BandedLU::substitute(const Real* values, const Real* inverse, int stride, Vector& x) const {
  Real* y = x.data();
  if (!order_.empty()) {
    for (std::size_t k = 0; k < order_.size(); ++k) work_[k] = y[order_[k]];
    y = work_.data();
  }
  for (const Block& blk : blocks_) {
    const Real* a = values + blk.offset * stride;
    const Real* inv = inverse + blk.first * stride;
    if (blk.b >= 1 && blk.b <= fixed_bands)
      (stride == 1 ? substitute_fixed_kernels : substitute_lane_kernels)[static_cast<std::size_t>(blk.b - 1)](
          a, inv, blk.n, y + blk.first);
    else
      substitute_any(a, inv, blk.n, blk.b, stride, y + blk.first);
  }
  if (!order_.empty())
    for (std::size_t k = 0; k < order_.size(); ++k) x[static_cast<Index>(order_[k])] = work_[k];
}

namespace {

// Sets a column of @p count complex entries to zero by unaligned vector stores
// (std::fill became `rep stos`, whose start-up took 7 % of the factorisation; so did
// memcpy from a zero vector, which GCC recognises as memset). The intrinsics' stores
// are unaligned in every compiler: a column is aligned to one entry only.
inline void zero_column(Complex* column, Index count) {
  Index i = 0;
#if defined(__AVX__)
  const __m256d zero = _mm256_setzero_pd();
  for (; i + 2 <= count; i += 2) _mm256_storeu_pd(reinterpret_cast<Real*>(column + i), zero);
#elif defined(__SSE2__)
  const __m128d zero = _mm_setzero_pd();
  for (; i < count; ++i) _mm_storeu_pd(reinterpret_cast<Real*>(column + i), zero);
#endif
  for (; i < count; ++i) column[i] = Complex(0.0);
}

// The complex band LU with partial pivoting, as LAPACK's zgbtf2/zgbtrs compute it
// (row interchanges within the band, the upper triangle widened to 2b by them), on
// interleaved (re, im) doubles written out as real arithmetic (std::complex's
// operator* guards against NaN through a library call; the parts stored apart
// measured 1.2–1.4 times slower). B > 0: the half-bandwidth known when compiling, its
// loops unrolled; B = 0: @p b at run time. A(i, c) is at c·ld + 2b + i − c,
// ld = 3b + 1.
//
// The matrix is read in as the elimination reaches it: column c (zeroed, then its
// stored entries @p values placed at @p positions, those of @p starts[c] …
// starts[c+1]) just before step c − 2b, so that each column is written, updated and
// finished while in cache (at 30 000 DOF, whose factors take 15 MB, filling the
// whole band first made the time vary from 2 to 3.6 ms between runs).
template <int B>
bool complex_factorize(Complex* ab, Index n, Index b_run, int* pivots, Complex* inverse, const Complex* values,
                       const int* starts, const Index* positions) {
  const Index b = B > 0 ? B : b_run, ld = 3 * b + 1, kv = 2 * b;
  auto at = [&](Index i, Index c) { return reinterpret_cast<Real*>(ab + c * ld + kv + i - c); };
  Index filled = 0;
  auto fill_to = [&](Index last) {
    for (; filled <= last; ++filled) {
      zero_column(ab + filled * ld, ld);
      for (int e = starts[filled]; e < starts[filled + 1]; ++e) ab[positions[e]] = values[e];
    }
  };
  Index ju = 0;
  for (Index j = 0; j < n; ++j) {
    fill_to(std::min(j + kv, n - 1));
    const Index km = std::min(b, n - 1 - j);
    Real* col = at(j, j);
    Index p = 0;
    Real best = std::abs(col[0]) + std::abs(col[1]);
    for (Index i = 1; i <= km; ++i)
      if (const Real m = std::abs(col[2 * i]) + std::abs(col[2 * i + 1]); m > best) best = m, p = i;
    pivots[j] = static_cast<int>(j + p);
    if (!(best > 0.0) || !std::isfinite(best)) return false;
    ju = std::max(ju, std::min(j + b + p, n - 1));
    if (p != 0)
      for (Index c = j; c <= ju; ++c) std::swap(ab[c * ld + kv + j - c], ab[c * ld + kv + j + p - c]);
    const Real pr = col[0], pi = col[1], d = pr * pr + pi * pi, rr = pr / d, ri = -pi / d;  // 1/pivot
    inverse[j] = Complex(rr, ri);
    Real* l = col + 2;
    const Index m = B > 0 && j + B < n ? B : km;
    for (Index i = 0; i < m; ++i) {
      const Real x = l[2 * i], y = l[2 * i + 1];
      l[2 * i] = x * rr - y * ri;
      l[2 * i + 1] = x * ri + y * rr;
    }
    for (Index c = j + 1; c <= ju; ++c) {
      Real* u = at(j, c);
      const Real ur = u[0], ui = u[1];
      if (ur == 0.0 && ui == 0.0) continue;
      Real* t = u + 2;
      for (Index i = 0; i < m; ++i) {
        const Real x = l[2 * i], y = l[2 * i + 1];
        t[2 * i] -= x * ur - y * ui;
        t[2 * i + 1] -= x * ui + y * ur;
      }
    }
  }
  return true;
}

template <int B>
void complex_substitute(const Complex* ab, Index n, Index b_run, const int* pivots, const Complex* inverse,
                        Complex* x) {
  const Index b = B > 0 ? B : b_run, ld = 3 * b + 1, kv = 2 * b;
  Real* y = reinterpret_cast<Real*>(x);
  for (Index j = 0; j < n; ++j) {  // L·y = P·b, unit diagonal
    if (pivots[j] != j) std::swap(x[j], x[pivots[j]]);
    const Index m = B > 0 && j + B < n ? B : std::min(b, n - 1 - j);
    const Real* l = reinterpret_cast<const Real*>(ab + j * ld + kv + 1);
    const Real yr = y[2 * j], yi = y[2 * j + 1];
    Real* t = y + 2 * (j + 1);
    for (Index i = 0; i < m; ++i) {
      t[2 * i] -= l[2 * i] * yr - l[2 * i + 1] * yi;
      t[2 * i + 1] -= l[2 * i] * yi + l[2 * i + 1] * yr;
    }
  }
  for (Index j = n - 1; j >= 0; --j) {  // U·x = y, upper bandwidth 2b
    const Real vr = y[2 * j], vi = y[2 * j + 1], ir = inverse[j].real(), ii = inverse[j].imag();
    const Real xr = vr * ir - vi * ii, xi = vr * ii + vi * ir;
    y[2 * j] = xr;
    y[2 * j + 1] = xi;
    const Index m = std::min(kv, j);
    const Real* u = reinterpret_cast<const Real*>(ab + j * ld + kv - m);  // A(j − m … j − 1, j)
    Real* t = y + 2 * (j - m);
    for (Index i = 0; i < m; ++i) {
      t[2 * i] -= u[2 * i] * xr - u[2 * i + 1] * xi;
      t[2 * i + 1] -= u[2 * i] * xi + u[2 * i + 1] * xr;
    }
  }
}

template <std::size_t... I>
constexpr auto complex_factor_kernels(std::index_sequence<I...>) {
  return std::array<bool (*)(Complex*, Index, Index, int*, Complex*, const Complex*, const int*, const Index*),
                    sizeof...(I)>{&complex_factorize<static_cast<int>(I)>...};
}
template <std::size_t... I>
constexpr auto complex_substitute_kernels(std::index_sequence<I...>) {
  return std::array<void (*)(const Complex*, Index, Index, const int*, const Complex*, Complex*), sizeof...(I)>{
      &complex_substitute<static_cast<int>(I)>...};
}
// Index 0: the run-time half-bandwidth; 1 … 16 compiled.
constexpr auto complex_factor = complex_factor_kernels(std::make_index_sequence<fixed_bands + 1>{});
constexpr auto complex_substitute_fixed = complex_substitute_kernels(std::make_index_sequence<fixed_bands + 1>{});

}  // namespace

bool ComplexBandedLU::analyse(const ComplexSparse& pattern, Index largest_bandwidth) {
  if (pattern.rows() != pattern.cols() || !pattern.isCompressed())
    throw Error("ComplexBandedLU::analyse: a matrix that is not square, or not compressed");
  Index b = 0;
  for (Index k = 0; k < pattern.outerSize(); ++k)
    for (ComplexSparse::InnerIterator it(pattern, k); it; ++it) b = std::max(b, std::abs(it.row() - it.col()));
  n_ = 0;
  order_.clear();
  const Index n = pattern.rows();
  std::vector<Index> position_of;  // of each unknown; empty: the unknowns' own order
  if (b > largest_bandwidth) {
    // Too wide in the given order: the reverse Cuthill–McKee order may fit.
    const std::vector<std::vector<Index>> graph = pattern_graph(pattern);
    order_ = reverse_cuthill_mckee(graph);
    position_of.resize(static_cast<std::size_t>(n));
    for (Index k = 0; k < n; ++k) position_of[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])] = k;
    b = ordered_bandwidth(graph, position_of);
    if (b > largest_bandwidth) {
      order_.clear();
      return false;
    }
  }
  n_ = n;
  b_ = b;
  ld_ = 3 * b_ + 1;
  ab_.resize(static_cast<std::size_t>(n_ * ld_));
  pivots_.assign(static_cast<std::size_t>(n_), 0);
  inverse_.assign(static_cast<std::size_t>(n_), Complex(0.0));
  positions_.clear();
  positions_.reserve(static_cast<std::size_t>(pattern.nonZeros()));
  gather_.clear();
  starts_.clear();
  if (order_.empty()) {
    for (Index k = 0; k < pattern.outerSize(); ++k)
      for (ComplexSparse::InnerIterator it(pattern, k); it; ++it)
        positions_.push_back(it.col() * ld_ + (2 * b_ + it.row() - it.col()));
    return true;
  }
  // Reordered: the entries gathered column by column of the new order.
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  starts_.push_back(0);
  for (Index c = 0; c < n_; ++c) {
    const Index q = order_[static_cast<std::size_t>(c)];
    for (int e = outer[q]; e < outer[q + 1]; ++e) {
      gather_.push_back(e);
      positions_.push_back(c * ld_ + (2 * b_ + position_of[static_cast<std::size_t>(inner[e])] - c));
    }
    starts_.push_back(static_cast<int>(gather_.size()));
  }
  values_.resize(gather_.size());
  work_.resize(n_);
  return true;
}

bool ComplexBandedLU::factorize(const ComplexSparse& A) {
  if (A.rows() != n_ || !A.isCompressed() || A.nonZeros() != static_cast<Index>(positions_.size()))
    throw Error("ComplexBandedLU::factorize: a matrix of another size or pattern than analysed");
  const std::size_t kernel = b_ <= fixed_bands ? static_cast<std::size_t>(b_) : 0;
  if (n_ == 0) return true;
  if (order_.empty())
    return complex_factor[kernel](ab_.data(), n_, b_, pivots_.data(), inverse_.data(), A.valuePtr(), A.outerIndexPtr(),
                                  positions_.data());
  for (std::size_t k = 0; k < gather_.size(); ++k) values_[k] = A.valuePtr()[gather_[k]];
  return complex_factor[kernel](ab_.data(), n_, b_, pivots_.data(), inverse_.data(), values_.data(), starts_.data(),
                                positions_.data());
}

void ComplexBandedLU::solve_in_place(ComplexVector& x) const {
  const std::size_t kernel = b_ <= fixed_bands ? static_cast<std::size_t>(b_) : 0;
  if (order_.empty()) {
    complex_substitute_fixed[kernel](ab_.data(), n_, b_, pivots_.data(), inverse_.data(), x.data());
    return;
  }
  for (Index k = 0; k < n_; ++k) work_(k) = x(order_[static_cast<std::size_t>(k)]);
  complex_substitute_fixed[kernel](ab_.data(), n_, b_, pivots_.data(), inverse_.data(), work_.data());
  for (Index k = 0; k < n_; ++k) x(order_[static_cast<std::size_t>(k)]) = work_(k);
}

}  // namespace feran
