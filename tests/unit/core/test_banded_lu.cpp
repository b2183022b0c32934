// The banded LU without pivoting (core/banded_lu.hpp) against a dense LU with
// pivoting, its refusal of a matrix that needs pivoting, the complex banded LU with
// partial pivoting against the dense one, and the sums of sparse matrices in place
// (assembly/sparse_sum.hpp) against Eigen's; the connected components that split a
// step's tangent into bands (core/components.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <utility>

#include <Eigen/Dense>

#include <feran/assembly/sparse_sum.hpp>
#include <feran/core/banded_lu.hpp>
#include <feran/core/components.hpp>
#include <feran/core/error.hpp>

namespace feran {
namespace {

// A random n × n matrix of half-bandwidth b: a symmetric positive definite part
// (diagonally dominant) plus a skew part of comparable size, like a step's tangent
// c_a·M + c_v·(C + Ω·G) + K.
SparseMatrix random_band(Index n, Index b, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<Real>> trip;
  for (Index i = 0; i < n; ++i) {
    trip.emplace_back(i, i, 2.0 * static_cast<Real>(b) + 1.0);
    for (Index j = i + 1; j <= std::min(n - 1, i + b); ++j) {
      const Real s = u(rng), k = u(rng);
      trip.emplace_back(i, j, s + k);
      trip.emplace_back(j, i, s - k);
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  A.makeCompressed();
  return A;
}

// S in the band's storage of @p lu (its values() after setting S).
std::vector<Real> kept(BandedLU& lu, const SparseMatrix& S) {
  lu.set_zero();
  lu.add(1.0, S);
  return lu.values();
}

TEST(BandedLU, SolvesLikeADenseLUWithPivoting) {
  // Half-bandwidths of the kernels compiled for one (1 … 16), of the general one (20),
  // and a matrix narrower than its band (n = 5).
  for (const auto& [n, b] : {std::pair<Index, Index>{57, 1}, {57, 3}, {57, 10}, {57, 16}, {57, 20}, {5, 4}}) {
    const SparseMatrix A = random_band(n, b, 7u + static_cast<unsigned>(b));
    ASSERT_EQ(BandedLU::half_bandwidth(A), b);
    BandedLU lu;
    lu.resize(n, b);
    lu.set_zero();
    lu.add(0.5, A);
    lu.add(0.5, A, lu.positions(A));  // the two ways of adding give A
    ASSERT_TRUE(lu.factorize());
    const Vector rhs = Vector::LinSpaced(n, -1.0, 2.0);
    Vector x = rhs;
    lu.solve_in_place(x);
    const Vector expected = Eigen::MatrixXd(A).partialPivLu().solve(rhs);
    // Both backward stable on a well-conditioned matrix: agreement to round-off.
    EXPECT_LT((x - expected).norm(), 1e-13 * expected.norm()) << "n = " << n << ", b = " << b;
  }
}

TEST(BandedLU, KeptPartsCombineIntoTheMatrixAtAnySpeed) {
  // A run on a speed ramp keeps A and B in the band's storage and sets A + Ω·B before
  // each factorisation: the same solution as the matrix added entry by entry.
  const Index n = 40, b = 6;
  const SparseMatrix A = random_band(n, b, 3u), B = random_band(n, b, 4u);
  BandedLU lu;
  lu.resize(n, b);
  const std::vector<Real> kept_a = kept(lu, A), kept_b = kept(lu, B);
  const Vector rhs = Vector::LinSpaced(n, 1.0, -3.0);
  for (const Real speed : {0.0, 0.25, -0.5}) {
    lu.set_combination(kept_a, speed, kept_b);
    ASSERT_TRUE(lu.factorize());
    Vector x = rhs;
    lu.solve_in_place(x);
    const SparseMatrix S = A + speed * B;
    const Vector expected = Eigen::MatrixXd(S).partialPivLu().solve(rhs);
    EXPECT_LT((x - expected).norm(), 1e-13 * expected.norm()) << "speed " << speed;
  }
  EXPECT_THROW(lu.set_combination(kept_a, 1.0, std::vector<Real>(3, 0.0)), Error);
}

TEST(BandedLU, SplitsUncoupledUnknownsIntoBandsOfTheirOwn) {
  // Three sets of unknowns interleaved as a rotor's are (four lateral, one axial, one
  // torsional DOF per node): the lateral set a band of half-bandwidth 3 in its own
  // numbering (5 in the whole), the axial and torsional ones tridiagonal (6 in the
  // whole). Each set is factorised on its own; the solution is the whole matrix's.
  const Index nodes = 9, n = 6 * nodes;
  const SparseMatrix lateral = random_band(4 * nodes, 3, 11u), axial = random_band(nodes, 1, 12u),
                     torsional = random_band(nodes, 1, 13u);
  std::vector<Eigen::Triplet<Real>> trip;
  const auto lateral_dof = [](Index i) { return 6 * (i / 4) + 1 + i % 4; };
  for (Index k = 0; k < lateral.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(lateral, k); it; ++it)
      trip.emplace_back(lateral_dof(it.row()), lateral_dof(it.col()), it.value());
  for (Index k = 0; k < axial.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(axial, k); it; ++it) trip.emplace_back(6 * it.row(), 6 * it.col(), it.value());
  for (Index k = 0; k < torsional.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(torsional, k); it; ++it)
      trip.emplace_back(6 * it.row() + 5, 6 * it.col() + 5, it.value());
  SparseMatrix A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  A.makeCompressed();
  ASSERT_EQ(BandedLU::half_bandwidth(A), 6);

  BandedLU lu;
  EXPECT_FALSE(lu.partition(n, {&A}, 2));  // the lateral band is 3 wide
  ASSERT_TRUE(lu.partition(n, {&A}, 64));
  EXPECT_EQ(lu.blocks(), 3);
  EXPECT_EQ(lu.bandwidth(), 3);
  // Storage: 36·7 + 2·9·3 numbers, against 54·13 for the whole band.
  EXPECT_EQ(lu.values().size(), std::size_t{36 * 7 + 2 * 9 * 3});
  lu.set_zero();
  lu.add(1.0, A, lu.positions(A));
  ASSERT_TRUE(lu.factorize());
  const Vector rhs = Vector::LinSpaced(n, -2.0, 1.0);
  Vector x = rhs;
  lu.solve_in_place(x);
  const Vector expected = Eigen::MatrixXd(A).partialPivLu().solve(rhs);
  EXPECT_LT((x - expected).norm(), 1e-13 * expected.norm());
  // The lanes in the split band: lane L holds A + L·A, plus 1 at the torsional set's
  // last diagonal entry (its block's offset counted), and solves as the single matrix.
  SparseMatrix corner(n, n);
  corner.insert(n - 1, n - 1) = 1.0;
  corner.makeCompressed();
  const std::vector<Real> kept_a = kept(lu, A);
  const std::vector<BandedLU::LaneAddition> additions{{lu.positions(corner)[0], {1.0, 1.0, 1.0, 1.0}}};
  ASSERT_EQ(lu.factorize_lanes(kept_a, {0.0, 1.0, 2.0, 3.0}, kept_a, additions), 0b1111u);
  for (int lane = 0; lane < BandedLU::lanes; ++lane) {
    Vector z = rhs;
    lu.solve_in_place(z, lane);
    const SparseMatrix S = (1.0 + lane) * A + corner;
    const Vector exact = Eigen::MatrixXd(S).partialPivLu().solve(rhs);
    EXPECT_LT((z - exact).norm(), 1e-13 * exact.norm()) << "lane " << lane;
  }
  // An entry coupling two sets lies outside every band.
  SparseMatrix coupling(n, n);
  coupling.insert(0, 1) = 1.0;
  coupling.makeCompressed();
  EXPECT_THROW(lu.positions(coupling), Error);
}

TEST(BandedLU, LanesFactoriseFourSpeedsAsTheSingleMatrixDoes) {
  // A ramp's next four tangents A + Ω_L·B (plus entries that change with speed, as a
  // speed-dependent bearing's), factorised together one per lane: each lane's solution
  // is the one factorize() gives for that matrix alone, to the last bit (the same
  // operations in the same order), and the dense LU's to round-off. Kernels compiled
  // for a band (3, 7, 16), the general one (20) and a matrix narrower than its band
  // (a rotor's split into components: SplitsUncoupledUnknownsIntoBandsOfTheirOwn).
  for (const auto& [n, b] : {std::pair<Index, Index>{57, 3}, {57, 7}, {57, 16}, {57, 20}, {5, 4}, {6, 1}}) {
    const SparseMatrix A = random_band(n, b, 21u + static_cast<unsigned>(b)),
                       B = random_band(n, b, 31u + static_cast<unsigned>(b));
    BandedLU lu;
    lu.resize(n, b);
    const std::vector<Real> kept_a = kept(lu, A), kept_b = kept(lu, B);
    const std::array<Real, BandedLU::lanes> speeds{0.1, 0.35, -0.2, 0.6};
    // Two entries, one of them twice (they add), sorted by position.
    SparseMatrix extra(n, n);
    extra.insert(n - 1, n - 2) = 1.0;
    extra.insert(0, 0) = 1.0;
    extra.makeCompressed();
    std::vector<Index> at = lu.positions(extra);  // (0, 0) first
    SparseMatrix unit_first(n, n), unit_last(n, n);
    unit_first.insert(0, 0) = 1.0;
    unit_last.insert(n - 1, n - 2) = 1.0;
    std::vector<BandedLU::LaneAddition> additions;
    for (const Index p : at) additions.push_back({p, {0.5, -0.25, 1.5, 0.0}});
    additions.push_back(additions.back());
    std::sort(additions.begin(), additions.end(),
              [](const BandedLU::LaneAddition& x, const BandedLU::LaneAddition& y) { return x.position < y.position; });
    ASSERT_EQ(lu.factorize_lanes(kept_a, speeds, kept_b, additions), 0b1111u);
    const Vector rhs = Vector::LinSpaced(n, -1.0, 2.0);
    for (int lane = 0; lane < BandedLU::lanes; ++lane) {
      Vector x = rhs;
      lu.solve_in_place(x, lane);
      BandedLU single;
      single.resize(n, b);
      single.set_combination(kept_a, speeds[static_cast<std::size_t>(lane)], kept_b);
      for (const auto& add : additions)  // each entry as a single-entry matrix, in order
        single.add(add.value[static_cast<std::size_t>(lane)], add.position == at[0] ? unit_first : unit_last);
      SparseMatrix S = A + speeds[static_cast<std::size_t>(lane)] * B;
      for (const auto& add : additions) {
        const Real v = add.value[static_cast<std::size_t>(lane)];
        S.coeffRef(add.position == at[0] ? 0 : n - 1, add.position == at[0] ? 0 : n - 2) += v;
      }
      ASSERT_TRUE(single.factorize());
      Vector y = rhs;
      single.solve_in_place(y);
      EXPECT_EQ(x, y) << "n = " << n << ", b = " << b << ", lane " << lane;
      const Vector expected = Eigen::MatrixXd(S).partialPivLu().solve(rhs);
      EXPECT_LT((x - expected).norm(), 1e-13 * expected.norm()) << "n = " << n << ", b = " << b << ", lane " << lane;
    }
    EXPECT_THROW(lu.factorize_lanes(kept_a, speeds, std::vector<Real>(3, 0.0), {}), Error);
    std::reverse(additions.begin(), additions.end());
    if (additions.front().position != additions.back().position) {
      EXPECT_THROW(lu.factorize_lanes(kept_a, speeds, kept_b, additions), Error);  // not sorted
    }
  }
}

TEST(BandedLU, LanesReportEachLaneThatNeedsPivoting) {
  // Lane 2's matrix has a zero first pivot (A + Ω·B with Ω = −1 cancels it); the
  // others factorise.
  SparseMatrix A(3, 3), B(3, 3);
  A.insert(0, 0) = 1.0, A.insert(0, 1) = 1.0, A.insert(1, 0) = 1.0, A.insert(1, 1) = 2.0, A.insert(2, 2) = 1.0;
  B.insert(0, 0) = 1.0;
  A.makeCompressed();
  B.makeCompressed();
  BandedLU lu;
  lu.resize(3, 1);
  lu.set_zero();
  lu.add(1.0, A);
  const std::vector<Real> kept_a = lu.values();
  lu.set_zero();
  lu.add(1.0, B);
  EXPECT_EQ(lu.factorize_lanes(kept_a, {0.0, 1.0, -1.0, 2.0}, lu.values(), {}), 0b1011u);
}

TEST(ConnectedComponents, NumberedByTheirFirstUnknownWithZerosJoiningOnlyAsPattern) {
  // 0–3 and 1–4 coupled, 2 alone; the entry (2, 4) stored as an explicit zero.
  SparseMatrix A(5, 5);
  A.insert(3, 0) = 1.0;
  A.insert(1, 4) = -2.0;
  A.insert(2, 4) = 0.0;
  A.makeCompressed();
  EXPECT_EQ(connected_components(5, {&A}, true), (std::vector<Index>{0, 1, 2, 0, 1}));
  EXPECT_EQ(connected_components(5, {&A}, false), (std::vector<Index>{0, 1, 1, 0, 1}));
  EXPECT_THROW(connected_components(4, {&A}, false), Error);
}

// A random complex n × n matrix of half-bandwidth b whose diagonal is small against
// its off-diagonal entries (a dynamic stiffness near a resonance): elimination
// without row interchanges would be unstable on it.
Eigen::SparseMatrix<Complex> random_complex_band(Index n, Index b, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<Complex>> trip;
  for (Index i = 0; i < n; ++i)
    for (Index j = std::max<Index>(0, i - b); j <= std::min(n - 1, i + b); ++j)
      trip.emplace_back(i, j, i == j ? Complex(1e-3 * u(rng), 1e-3 * u(rng)) : Complex(u(rng), u(rng)));
  Eigen::SparseMatrix<Complex> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  A.makeCompressed();
  return A;
}

TEST(ComplexBandedLU, SolvesLikeADenseLUWithPartialPivoting) {
  // The compiled kernels (b = 1, 3, 10, 16), the run-time one (20), a matrix narrower
  // than its band (n = 5). The same row interchanges as the dense LU's are not
  // required (within the band they are LAPACK's, zgbtrf); the solutions agree to the
  // round-off of the conditioning: 1e-9 relative (these matrices' condition numbers
  // are 1e2 … 1e4, measured by the dense LU's rcond).
  for (const auto& [n, b] : {std::pair<Index, Index>{57, 1}, {57, 3}, {57, 10}, {57, 16}, {57, 20}, {5, 4}}) {
    const auto A = random_complex_band(n, b, 11u + static_cast<unsigned>(b));
    ComplexBandedLU lu;
    ASSERT_TRUE(lu.analyse(A, 64));
    EXPECT_EQ(lu.bandwidth(), std::min(b, n - 1));
    ASSERT_TRUE(lu.factorize(A));
    const ComplexVector rhs = ComplexVector::LinSpaced(n, Complex(-1.0, 0.5), Complex(2.0, -1.0));
    ComplexVector x = rhs;
    lu.solve_in_place(x);
    const Eigen::MatrixXcd dense(A);
    const ComplexVector expected = dense.partialPivLu().solve(rhs);
    EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm()) << "n = " << n << ", b = " << b;
    // And the residual itself, independent of the dense LU: backward stable.
    EXPECT_LT((dense * x - rhs).norm(), 1e-12 * (dense.norm() * x.norm())) << "n = " << n << ", b = " << b;
  }
}

TEST(ComplexBandedLU, RefusesASingularMatrixAndAWideBand) {
  auto A = random_complex_band(20, 3, 5u);
  ComplexBandedLU lu;
  EXPECT_FALSE(lu.analyse(A, 2));  // the band is wider than allowed
  ASSERT_TRUE(lu.analyse(A, 64));
  for (Index k = 0; k < A.outerSize(); ++k)  // column 7 zero: no pivot there
    for (Eigen::SparseMatrix<Complex>::InnerIterator it(A, k); it; ++it)
      if (it.col() == 7) it.valueRef() = 0.0;
  EXPECT_FALSE(lu.factorize(A));
}

TEST(BandedLU, RefusesAMatrixThatNeedsPivoting) {
  SparseMatrix A(3, 3);
  A.insert(0, 1) = 1.0;
  A.insert(1, 0) = 1.0;
  A.insert(1, 1) = 1.0;
  A.insert(2, 2) = 1.0;
  A.makeCompressed();
  BandedLU lu;
  lu.resize(3, 1);
  lu.set_zero();
  lu.add(1.0, A);
  EXPECT_FALSE(lu.factorize());  // a zero first pivot
}

TEST(BandedLU, RefusesEntriesOutsideTheBand) {
  const SparseMatrix A = random_band(10, 3, 1u);
  BandedLU lu;
  lu.resize(10, 2);
  EXPECT_THROW(lu.add(1.0, A), Error);
  EXPECT_THROW(static_cast<void>(lu.positions(A)), Error);
}

TEST(SparseSum, EqualsEigensSumInThePatternsUnion) {
  const SparseMatrix A = random_band(30, 2, 3u), B = random_band(30, 4, 5u);
  SparseMatrix C(30, 30);
  C.insert(29, 0) = 3.0;  // outside both
  C.makeCompressed();
  const SparseSum sum({&A, &B, &C});
  SparseMatrix out;
  for (const Real w : {0.0, 2.5, -1.0}) {
    sum.evaluate({1.0, w, 2.0}, {&A, &B, &C}, out);
    const SparseMatrix expected = A + w * B + 2.0 * C;
    // The same sums, perhaps in another order or fused (a compiler's choice): equal
    // to the round-off of three terms.
    const Eigen::MatrixXd difference = Eigen::MatrixXd(out) - Eigen::MatrixXd(expected);
    EXPECT_LE(difference.cwiseAbs().maxCoeff(), 4e-16 * Eigen::MatrixXd(expected).cwiseAbs().maxCoeff()) << "w = " << w;
    EXPECT_EQ(out.nonZeros(), SparseMatrix(A + B + C).nonZeros());  // the union, zeros kept
  }
  EXPECT_THROW(sum.evaluate({1.0, 1.0}, {&A, &B}, out), Error);
}

}  // namespace
}  // namespace feran
