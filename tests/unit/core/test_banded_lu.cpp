// The banded LU without pivoting (core/banded_lu.hpp) against a dense LU with
// pivoting, its refusal of a matrix that needs pivoting, the complex banded LU with
// partial pivoting against the dense one, and the sums of sparse matrices in place
// (assembly/sparse_sum.hpp) against Eigen's; the connected components that split a
// step's tangent into bands (core/components.hpp); the reverse Cuthill–McKee order
// that gives a band to unknowns numbered far apart (core/ordering.hpp).
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
#include <feran/core/ordering.hpp>

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

// A set in @p lu (partitioned for its pattern), factorised and solved for @p rhs: the
// dense LU's solution to round-off (1e-13: these matrices are well conditioned), which
// is returned.
Vector expect_solves_as_dense(BandedLU& lu, const SparseMatrix& A, const Vector& rhs) {
  lu.set_zero();
  lu.add(1.0, A, lu.positions(A));
  EXPECT_TRUE(lu.factorize());
  Vector x = rhs;
  lu.solve_in_place(x);
  const Vector expected = Eigen::MatrixXd(A).partialPivLu().solve(rhs);
  EXPECT_LT((x - expected).norm(), 1e-13 * expected.norm());
  return expected;
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
  const Vector rhs = Vector::LinSpaced(n, -2.0, 1.0);
  const Vector expected = expect_solves_as_dense(lu, A, rhs);
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

// A random permutation of 0 … n − 1 (the unknown at each position).
std::vector<Index> shuffled(Index n, unsigned seed) {
  std::vector<Index> p(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) p[static_cast<std::size_t>(i)] = i;
  std::shuffle(p.begin(), p.end(), std::mt19937(seed));
  return p;
}

// P·A·Pᵀ: row and column position k of the result is unknown @p order[k] of A.
template <class Sparse>
Sparse permuted(const Sparse& A, const std::vector<Index>& order) {
  std::vector<Index> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) position[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
  std::vector<Eigen::Triplet<typename Sparse::Scalar>> trip;
  for (Index k = 0; k < A.outerSize(); ++k)
    for (typename Sparse::InnerIterator it(A, k); it; ++it)
      trip.emplace_back(position[static_cast<std::size_t>(it.row())], position[static_cast<std::size_t>(it.col())],
                        it.value());
  Sparse B(A.rows(), A.cols());
  B.setFromTriplets(trip.begin(), trip.end());
  B.makeCompressed();
  return B;
}

std::vector<Index> positions_of(const std::vector<Index>& order) {
  std::vector<Index> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) position[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
  return position;
}

TEST(ReverseCuthillMcKee, GivesScrambledBandsABandAgain) {
  // A band of half-bandwidth b with its unknowns scrambled has a half-bandwidth near
  // n; the ordering must be a permutation and give at most 2b − 1 (Cuthill–McKee's
  // bound: an entry joins two nodes of one level or of adjacent levels, and a level
  // of a band's graph started at its end holds at most b nodes). Two bands, one
  // with an entry joining its ends (a ring), make two components: each numbered in
  // one run.
  const Index n = 300, b = 5;
  const SparseMatrix band = random_band(n, b, 21u);
  const SparseMatrix scrambled = permuted(band, shuffled(n, 22u));
  ASSERT_GT(BandedLU::half_bandwidth(scrambled), 250);
  const auto graph = pattern_graph(n, {&scrambled});
  const std::vector<Index> order = reverse_cuthill_mckee(graph);
  std::vector<Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (Index k = 0; k < n; ++k) ASSERT_EQ(sorted[static_cast<std::size_t>(k)], k);
  EXPECT_LE(ordered_bandwidth(graph, positions_of(order)), 2 * b - 1);
  EXPECT_EQ(BandedLU::half_bandwidth(permuted(scrambled, order)), ordered_bandwidth(graph, positions_of(order)));

  // Two components, interleaved: a chain of 40 nodes and a ring of 30 (each node
  // joined to its two neighbours, the last to the first).
  std::vector<Eigen::Triplet<Real>> trip;
  std::vector<Index> chain_nodes, ring_nodes;
  for (Index i = 0; i < 70; ++i) {
    trip.emplace_back(i, i, 1.0);
    (i % 7 < 3 ? ring_nodes : chain_nodes).push_back(i);
  }
  for (std::size_t k = 0; k + 1 < chain_nodes.size(); ++k) trip.emplace_back(chain_nodes[k], chain_nodes[k + 1], 1.0);
  for (std::size_t k = 0; k < ring_nodes.size(); ++k)
    trip.emplace_back(ring_nodes[k], ring_nodes[(k + 1) % ring_nodes.size()], 1.0);
  SparseMatrix two(70, 70);
  two.setFromTriplets(trip.begin(), trip.end());
  const auto g2 = pattern_graph(70, {&two});
  const std::vector<Index> order2 = reverse_cuthill_mckee(g2);
  const std::vector<Index> component = connected_components(70, {&two}, false);
  ASSERT_EQ(*std::max_element(component.begin(), component.end()), 1);
  Index changes = 0;
  for (std::size_t k = 1; k < order2.size(); ++k)
    changes += component[static_cast<std::size_t>(order2[k])] != component[static_cast<std::size_t>(order2[k - 1])];
  EXPECT_EQ(changes, 1);
  // A ring numbered from one node outwards: neighbours at most 2 apart.
  EXPECT_LE(ordered_bandwidth(g2, positions_of(order2)), 2);
}

TEST(BandedLU, ReordersAComponentTooWideInTheUnknownsOrder) {
  // The scrambled band: too wide as numbered, a band again in the reverse
  // Cuthill–McKee order; factorised and solved there, the solution is the matrix's,
  // to round-off (1e-13: well conditioned, as above), and so are the lanes'.
  const Index n = 200, b = 4;
  const SparseMatrix A = permuted(random_band(n, b, 31u), shuffled(n, 32u));
  BandedLU lu;
  ASSERT_TRUE(lu.partition(n, {&A}, 64));
  EXPECT_LE(lu.bandwidth(), 2 * b - 1);
  EXPECT_FALSE(lu.partition(n, {&A}, b - 1));  // no order is narrower than the band itself
  ASSERT_TRUE(lu.partition(n, {&A}, 64));
  const Vector rhs = Vector::LinSpaced(n, -2.0, 1.0);
  const Vector expected = expect_solves_as_dense(lu, A, rhs);
  const std::vector<Real> kept_a = kept(lu, A);
  ASSERT_EQ(lu.factorize_lanes(kept_a, {1.0, 2.0, 3.0, 4.0}, kept_a, {}), 0b1111u);
  for (int lane = 0; lane < BandedLU::lanes; ++lane) {
    Vector z = rhs;
    lu.solve_in_place(z, lane);
    EXPECT_LT(((2.0 + lane) * z - expected).norm(), 1e-13 * expected.norm()) << "lane " << lane;
  }
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

TEST(ComplexBandedLU, ReordersABandTooWideInTheUnknownsOrder) {
  // A dynamic stiffness whose unknowns are numbered far apart (a support node last,
  // joined to the first journal): too wide as given, banded in the reverse
  // Cuthill–McKee order, and solved there with partial pivoting as the dense LU
  // solves it (1e-9 relative, as above; residual 1e-12 backward).
  const Index n = 120, b = 6;
  const auto A = permuted(random_complex_band(n, b, 41u), shuffled(n, 42u));
  ComplexBandedLU lu;
  ASSERT_TRUE(lu.analyse(A, 64));
  EXPECT_TRUE(lu.reordered());
  EXPECT_LE(lu.bandwidth(), 2 * b - 1);
  ASSERT_TRUE(lu.factorize(A));
  const ComplexVector rhs = ComplexVector::LinSpaced(n, Complex(1.0, -0.5), Complex(-2.0, 3.0));
  ComplexVector x = rhs;
  lu.solve_in_place(x);
  const Eigen::MatrixXcd dense(A);
  const ComplexVector expected = dense.partialPivLu().solve(rhs);
  EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm());
  EXPECT_LT((dense * x - rhs).norm(), 1e-12 * (dense.norm() * x.norm()));
  // A band that fits as given keeps its order.
  const auto narrow = random_complex_band(n, b, 43u);
  ASSERT_TRUE(lu.analyse(narrow, 64));
  EXPECT_FALSE(lu.reordered());
  EXPECT_EQ(lu.bandwidth(), b);
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
