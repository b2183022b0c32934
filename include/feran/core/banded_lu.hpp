#pragma once
/// @file
/// LU factorisation of a banded sparse matrix without pivoting, for the tangent
/// matrices of time integration. A rotor's matrices in node order have a
/// half-bandwidth of a few DOFs (10 for a straight shaft line: two nodes of six DOFs,
/// less the held ones), and S = c_a·M + c_v·D + c_x·K of an implicit step is
/// dominated by its symmetric positive definite mass term for the steps integrators
/// take, so Gaussian elimination without pivoting is stable for it (Golub & Van Loan
/// 2013, §4.4: no pivoting is needed when the symmetric part is positive definite).
/// A pivot that is nevertheless small against its column refuses the factorisation,
/// and the caller falls back to a pivoting sparse LU.
///
/// Cost at a half-bandwidth b: factorisation 2·n·b² flops, solve 4·n·b, storage
/// n·(2b + 1); kernels compiled for each b up to 16 (a rotor's are 4 … 12). At 1210 DOF
/// (b = 10) about 15 µs and 9 µs on the benchmark machine, against 850 µs and 26 µs for
/// Eigen's supernodal SparseLU (docs/performance.md).

#include <array>
#include <vector>

#include <feran/core/types.hpp>

namespace feran {

class BandedLU {
 public:
  /// Half-bandwidth max |i − j| over the entries of @p pattern (square).
  static Index half_bandwidth(const SparseMatrix& pattern);

  /// Prepares for n × n matrices of half-bandwidth @p b.
  void resize(Index n, Index b);
  /// Prepares for n × n matrices whose entries lie in the union of @p patterns' (their
  /// explicit zeros included), split into the connected components of that union's
  /// graph — a rotor's lateral, axial and torsional motions, which no matrix of a
  /// straight shaft line couples: each component is a band of its own in the
  /// unknowns' order, narrower than the whole (lateral: 7 against 10), so that the
  /// factorisation costs about a third and the solve half. A component whose
  /// half-bandwidth in that order exceeds @p largest_bandwidth is taken in the reverse
  /// Cuthill–McKee order (core/ordering.hpp); false (and nothing allocated) when it is
  /// wider in that order too.
  bool partition(Index n, const std::vector<const SparseMatrix*>& patterns, Index largest_bandwidth);
  Index size() const { return n_; }
  /// The largest half-bandwidth of a component (the band's with one).
  Index bandwidth() const { return b_; }
  /// The components (1 after resize()).
  Index blocks() const { return static_cast<Index>(blocks_.size()); }

  /// Sets the matrix to zero, then adds c·S for each term (S's entries must lie in
  /// the band).
  void set_zero();
  void add(Real c, const SparseMatrix& S);
  /// Where each stored entry of @p S (compressed) lies in the band's storage, for
  /// add(c, S, positions) on matrices of that pattern; throws for an entry outside.
  std::vector<Index> positions(const SparseMatrix& S) const;
  /// The same as add(c, S) for a compressed S of the pattern @p positions were made for.
  void add(Real c, const SparseMatrix& S, const std::vector<Index>& positions);

  /// The matrix set, in the band's storage (each component's band after the other's:
  /// column j's rows j − b … j + b at j·(2b + 1) + i − j + b, in the component's own
  /// numbering), to be kept and combined by set_combination().
  const std::vector<Real>& values() const { return a_; }
  /// Sets the matrix to A + c·B, both values() of this band's size.
  void set_combination(const std::vector<Real>& A, Real c, const std::vector<Real>& B);

  /// Factorises the matrix set; false when a pivot is below 1e-10 of the largest
  /// entry of its column (or not finite): the matrix then needs pivoting.
  bool factorize();
  /// Solves A·x = b in place with the factors. (Not for concurrent calls on one
  /// object split into components: they share a workspace.)
  void solve_in_place(Vector& x) const;

  /// Matrices of this band factorised together, one in each lane of a vector: a run's
  /// tangents at its next steps' speeds. A factorisation's chain through its pivots
  /// (a division, the multipliers, the next column's update) bounds one matrix's
  /// time, not the arithmetic, so that four take about the time of one.
  static constexpr int lanes = 4;
  /// An entry added to the lanes' matrices: lane L's value[L] at @p position in the
  /// band's storage (as positions() gives).
  struct LaneAddition {
    Index position;
    std::array<Real, lanes> value;
  };
  /// Factorises, one in each lane, the matrices A + c[L]·B plus @p additions (sorted
  /// by position; A and B values() of this band's size), in storage of their own: the
  /// single matrix and its factors are left as they are. A bit for each lane that
  /// factorised (as factorize()'s true).
  unsigned factorize_lanes(const std::vector<Real>& A, const std::array<Real, lanes>& c, const std::vector<Real>& B,
                           const std::vector<LaneAddition>& additions);
  /// Solves A·x = b in place with lane @p lane's factors.
  void solve_in_place(Vector& x, int lane) const;

 private:
  /// Where entry (i, j) lies in a_, or −1 outside the band (or between components).
  Index index(Index i, Index j) const;
  /// Forward and back substitution with factors whose entries lie @p stride apart.
  void substitute(const Real* values, const Real* inverse, int stride, Vector& x) const;

  struct Block {
    Index n, b;    // unknowns, half-bandwidth
    Index offset;  // of its band in a_
    Index first;   // of its unknowns in inverse_ and the solve's gathered vector
  };
  Index n_ = 0, b_ = 0;
  std::vector<Block> blocks_;
  std::vector<Index> block_of_, local_of_;  // per unknown; empty: one block, unknowns in order
  std::vector<Index> order_;                // the unknowns component by component
  std::vector<Real> a_;  // each component's column j: rows j − b … j + b, at offset + j·(2b + 1) + (i − j + b)
  std::vector<Real> inverse_;       // 1 / U(k, k)
  mutable std::vector<Real> work_;  // solve_in_place's gathered right-hand side
  // The lanes' matrices and 1 / U(k, k), lane-interleaved (entry e of lane L at
  // e·lanes + L from a vector-aligned start).
  std::vector<Real> lane_values_, lane_inverse_;
};

/// LU factorisation with partial pivoting of a complex banded sparse matrix, for the
/// dynamic stiffness K + iωD − ω²M of a response point: it is not definite near a
/// resonance, so rows are pivoted within the band as LAPACK's zgbtrf does (the upper
/// triangle then has up to 2b diagonals), with kernels compiled for each b ≤ 16 (on a
/// 3010-DOF rotor, b = 10, several times faster than OpenBLAS's zgbtrf, whose
/// unblocked small-band path is call-bound; docs/performance.md). Cost at a
/// half-bandwidth b: factorisation about 8·n·b·(b … 2b) real flops, solve 8·n·4b.
class ComplexBandedLU {
 public:
  using ComplexSparse = Eigen::SparseMatrix<Complex>;

  /// Prepares for matrices of @p pattern's size, half-bandwidth and pattern
  /// (compressed). Where the unknowns' own order has a half-bandwidth above @p
  /// largest_bandwidth, they are taken in the reverse Cuthill–McKee order
  /// (core/ordering.hpp; the same for rows and columns); false when that too is wider.
  bool analyse(const ComplexSparse& pattern, Index largest_bandwidth);
  Index size() const { return n_; }
  /// The half-bandwidth in the order factorised.
  Index bandwidth() const { return b_; }
  /// The unknowns were reordered to fit the band.
  bool reordered() const { return !order_.empty(); }

  /// Factorises @p A (the pattern analysed); false when a column has no non-zero
  /// pivot (exactly singular) or is not finite.
  bool factorize(const ComplexSparse& A);
  /// Solves A·x = b in place with the factors.
  void solve_in_place(ComplexVector& x) const;
  /// The row interchanged with each row k (k itself where none), as LAPACK's ipiv;
  /// positions of the order factorised (reordered(): the reverse Cuthill–McKee one).
  const std::vector<int>& pivots() const { return pivots_; }

 private:
  Index n_ = 0, b_ = 0, ld_ = 1;
  std::vector<Complex> ab_;       // LAPACK's band storage: A(i, j) at j·ld + (2b + i − j)
  std::vector<Index> positions_;  // of the pattern's stored entries in ab_
  std::vector<int> pivots_;       // row interchanged with each row, as LAPACK's ipiv (0-based)
  std::vector<Complex> inverse_;  // 1 / U(k, k)
  // Where the given order is too wide: the unknown at each position of the reverse
  // Cuthill–McKee order (core/ordering.hpp), the matrix's entries in that order
  // (gathered from @c gather_, each column's from @c starts_), and the solve's
  // reordered right-hand side. Empty in the given order.
  std::vector<Index> order_;
  std::vector<int> gather_, starts_;
  std::vector<Complex> values_;
  mutable ComplexVector work_;
};

}  // namespace feran
