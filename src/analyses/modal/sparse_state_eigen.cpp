#include "state_eigen.hpp"

#include <algorithm>
#include <cstdint>

#include <Eigen/Eigenvalues>

#include <Eigen/SparseLU>
#include <Spectra/GenEigsRealShiftSolver.h>
#include <fmt/format.h>

namespace feran::detail {

namespace {

// Spectra operator y = (A − σI)⁻¹x for the state matrix A = [[0, I], [−M⁻¹K, −M⁻¹D]],
// applied without forming A: with x = (x1, x2) and y = (y1, y2),
//   (K + σD + σ²M)·y1 = −(M·x2 + (D + σM)·x1),  y2 = x1 + σ·y1.
class StateShiftInvert {
 public:
  using Scalar = Real;

  StateShiftInvert(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K)
      : M_(M), D_(D), K_(K), n_(M.rows()) {}

  Index rows() const { return 2 * n_; }
  Index cols() const { return 2 * n_; }

  void set_shift(const Scalar& sigma) {
    sigma_ = sigma;
    DsM_ = D_ + sigma * M_;
    SparseMatrix Q = K_ + sigma * D_ + sigma * sigma * M_;
    Q.makeCompressed();
    lu_.analyzePattern(Q);
    lu_.factorize(Q);
    ok_ = lu_.info() == Eigen::Success;
  }
  bool ok() const { return ok_; }

  void perform_op(const Scalar* x_in, Scalar* y_out) const {
    Eigen::Map<const Vector> x1(x_in, n_), x2(x_in + n_, n_);
    Eigen::Map<Vector> y1(y_out, n_), y2(y_out + n_, n_);
    rhs_ = -(M_ * x2 + DsM_ * x1);
    y1 = lu_.solve(rhs_);
    y2 = x1 + sigma_ * y1;
  }

 private:
  const SparseMatrix& M_;
  const SparseMatrix& D_;
  const SparseMatrix& K_;
  Index n_;
  Real sigma_ = 0.0;
  SparseMatrix DsM_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  bool ok_ = false;
  mutable Vector rhs_;
};

// Each oscillatory mode is a conjugate pair of state eigenvalues; ask for a few
// more so that real (overdamped, rigid) eigenvalues do not crowd modes out. An odd
// count: with a real shift both members of a pair are equally near it, and the
// restart then keeps whole pairs (the last one is completed), which converges
// reliably; even counts were seen to stall for 1000 restarts on undamped rotors.
Index n_eigenvalues(Index n, Index n_wanted) { return std::min<Index>(2 * n - 2, 2 * n_wanted + 3); }

// The state vectors of the Ritz pairs (and their values θ) of the eigenvalues of
// the shift-inverted operator largest in magnitude, from an unrestarted Arnoldi
// factorisation that grows until they have converged.
struct RitzPairs {
  Eigen::VectorXcd values;   // θ
  Eigen::MatrixXcd vectors;  // the displacement part of each Ritz vector
  Index operations = 0;      // operator applications
  bool converged = false;
};

// Arnoldi without restarts, orthogonalised by classical Gram–Schmidt with one
// selective reorthogonalisation (DGKS: "twice is enough"). The factorisation
// starts at about two vectors per wanted eigenvalue and grows by half the wanted
// count until the @p nev eigenvalues of largest |θ| (with any conjugate at the cut)
// have converged — residual |β·e_mᵀy| ≤ tol·|θ|, the criterion of Spectra's
// restarted solver — or the subspace reaches @p max_size (not converged: the caller
// falls back to the restarted solver). Deterministic: a fixed start vector.
RitzPairs growing_arnoldi(const StateShiftInvert& op, Index nev, Index max_size, Real tol) {
  const Index N = op.rows();
  RitzPairs out;
  max_size = std::min(max_size, N);
  Matrix V(N, max_size + 1);
  Matrix H = Matrix::Zero(max_size + 1, max_size);
  // Fixed pseudo-random start vector (a linear congruential sequence).
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (Index i = 0; i < N; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    V(i, 0) = static_cast<Real>(state >> 11) * 0x1.0p-53 - 0.5;
  }
  V.col(0).normalize();
  Vector w(N), h(max_size), h2(max_size);
  Index m = 0;
  Index check_at = std::min(max_size, std::max<Index>(2 * nev + 1, 20));
  const Index growth = std::max<Index>(nev / 2, 8);
  while (m < max_size) {
    op.perform_op(V.col(m).data(), w.data());
    ++out.operations;
    const Index k = m + 1;
    h.head(k).noalias() = V.leftCols(k).transpose() * w;
    w.noalias() -= V.leftCols(k) * h.head(k);
    Real beta = w.norm();
    // A second pass where cancellation may have cost orthogonality (the DGKS
    // criterion ‖w‖ < ‖h‖/√2); then the basis is orthogonal to working precision.
    if (beta < 0.717 * h.head(k).norm()) {
      h2.head(k).noalias() = V.leftCols(k).transpose() * w;
      w.noalias() -= V.leftCols(k) * h2.head(k);
      h.head(k) += h2.head(k);
      beta = w.norm();
    }
    H.col(m).head(k) = h.head(k);
    H(k, m) = beta;
    m = k;
    // A (numerically) invariant subspace: its Ritz pairs are exact.
    const bool invariant = beta <= 1e-14 * H.col(m - 1).head(k).norm();
    if (!invariant) V.col(m) = w / beta;
    if (m < check_at && !invariant) continue;
    if (m < nev) return out;  // invariant before holding the wanted count
    check_at = std::min(max_size, m + growth);

    const Eigen::EigenSolver<Matrix> es(H.topLeftCorner(m, m));
    if (es.info() != Eigen::Success) return out;
    const Eigen::VectorXcd theta = es.eigenvalues();
    std::vector<Index> order(static_cast<std::size_t>(m));
    for (Index i = 0; i < m; ++i) order[static_cast<std::size_t>(i)] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](Index a, Index b) { return std::abs(theta(a)) > std::abs(theta(b)); });
    Index take = nev;
    // A conjugate pair is not split at the cut.
    while (take < m && std::abs(std::abs(theta(order[static_cast<std::size_t>(take)])) -
                                std::abs(theta(order[static_cast<std::size_t>(take - 1)]))) <=
                           1e-12 * std::abs(theta(order[static_cast<std::size_t>(take - 1)])))
      ++take;
    const Eigen::MatrixXcd Y = es.eigenvectors();  // unit columns
    bool all = true;
    for (Index c = 0; c < take && all; ++c) {
      const Index i = order[static_cast<std::size_t>(c)];
      const Real residual = invariant ? 0.0 : beta * std::abs(Y(m - 1, i));
      all = residual <= tol * std::max(std::abs(theta(i)), 1e-300);
    }
    if (!all && !invariant) continue;
    out.converged = all || invariant;
    out.values.resize(take);
    out.vectors.resize(N / 2, take);
    for (Index c = 0; c < take; ++c) {
      const Index i = order[static_cast<std::size_t>(c)];
      out.values(c) = theta(i);
      out.vectors.col(c) = V.topLeftCorner(N / 2, m).cast<Complex>() * Y.col(i);
    }
    return out;
  }
  return out;
}

}  // namespace

// Three Krylov vectors per wanted eigenvalue: 2–3 restarts on the benchmark rotors,
// where 2·nev + 1 needed from 1 to over 1000.
Index arnoldi_subspace_size(Index n, Index n_wanted) {
  return std::min<Index>(2 * n, std::max<Index>(3 * n_eigenvalues(n, n_wanted) + 1, 20));
}

StateEigenpairs sparse_state_eigen(const SparseMatrix& M, const SparseMatrix& D,
                                   const SparseMatrix& K, Index n_wanted, Real sigma) {
  const Index n = M.rows();
  StateEigenpairs out;
  out.info.method = "shift-invert-arnoldi";
  StateShiftInvert op(M, D, K);
  const Index nev = n_eigenvalues(n, n_wanted);
  const Index ncv = arnoldi_subspace_size(n, n_wanted);
  constexpr Real tol = 1e-10;
  op.set_shift(sigma);
  if (!op.ok()) {
    out.info.converged = false;
    out.info.message = fmt::format("K + σD + σ²M is singular at the shift σ = {} rad/s", sigma);
    return out;
  }
  // First an Arnoldi factorisation grown only as far as the wanted eigenvalues need;
  // when they have not converged within the restarted solver's subspace size,
  // Spectra's implicitly restarted Arnoldi takes over.
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
  RitzPairs ritz = growing_arnoldi(op, nev, ncv, tol);
  if (ritz.converged) {
    out.info.method = "shift-invert-arnoldi";
    out.info.iterations = 1;
    out.info.n_converged = ritz.values.size();
    values = ritz.values.unaryExpr([sigma](const Complex& t) { return Complex(sigma) + 1.0 / t; });
    vectors = std::move(ritz.vectors);
  } else {
    Spectra::GenEigsRealShiftSolver<StateShiftInvert> solver(op, nev, ncv, sigma);
    solver.init();
    const Index n_conv = solver.compute(Spectra::SortRule::LargestMagn, 1000, tol,
                                        Spectra::SortRule::LargestMagn);
    out.info.iterations = solver.num_iterations();
    out.info.n_converged = n_conv;
    if (solver.info() != Spectra::CompInfo::Successful) {
      out.info.converged = false;
      out.info.message = fmt::format("Arnoldi iteration converged {} of {} eigenvalues", n_conv, nev);
    }
    values = solver.eigenvalues();
    vectors = solver.eigenvectors().topRows(n);
  }
  // Keep one eigenvalue of each conjugate pair (Im p ≥ 0). When the iteration
  // returned only the lower member of a pair, keep its conjugate instead.
  std::vector<std::pair<Index, bool>> keep;  // (column, conjugate it)
  for (Index j = 0; j < values.size(); ++j) {
    if (values(j).imag() >= 0.0) {
      keep.emplace_back(j, false);
      continue;
    }
    bool has_partner = false;
    for (Index i = 0; i < values.size(); ++i)
      has_partner = has_partner || std::abs(values(i) - std::conj(values(j))) <= 1e-8 * std::abs(values(j));
    if (!has_partner) keep.emplace_back(j, true);
  }
  out.values.resize(static_cast<Index>(keep.size()));
  out.vectors.resize(n, static_cast<Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const auto c = static_cast<Index>(k);
    const auto [j, conjugate] = keep[k];
    out.values(c) = conjugate ? std::conj(values(j)) : values(j);
    out.vectors.col(c) = conjugate ? Eigen::VectorXcd(vectors.col(j).conjugate()) : Eigen::VectorXcd(vectors.col(j));
    const Real norm = out.vectors.col(c).norm();
    if (norm > 0) out.vectors.col(c) /= norm;
  }
  return out;
}

}  // namespace feran::detail
