#pragma once
// Shift-invert operator of the state-space form and an Arnoldi factorisation grown
// until the wanted Ritz values converge, for real and complex (axisymmetric rotor)
// problems. Private to analyses/modal: included by sparse_state_eigen.cpp and
// sparse_complex_eigen.cpp, which are compiled apart (each instantiates one scalar
// type; together they were the slowest file of the build).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>

#include <fmt/format.h>

#include <feran/core/types.hpp>

#include "state_eigen.hpp"

namespace feran::detail {

// Operator y = (A − σI)⁻¹x for the state matrix A = [[0, I], [−M⁻¹K, −M⁻¹D]] (real
// for Spectra, or complex), applied without forming A: with x = (x1, x2) and
// y = (y1, y2),
//   (K + σD + σ²M)·y1 = −(M·x2 + (D + σM)·x1),  y2 = x1 + σ·y1.
template <class S>
class StateShiftInvert {
 public:
  using Scalar = S;
  using Sparse = Eigen::SparseMatrix<S>;
  using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1>;

  StateShiftInvert(const Sparse& M, const Sparse& D, const Sparse& K) : M_(M), D_(D), K_(K), n_(M.rows()) {}

  Index rows() const { return 2 * n_; }
  Index cols() const { return 2 * n_; }

  void set_shift(const Scalar& sigma) {
    sigma_ = sigma;
    DsM_ = D_ + sigma * M_;
    Sparse Q = K_ + sigma * D_ + sigma * sigma * M_;
    Q.makeCompressed();
    lu_.analyzePattern(Q);
    lu_.factorize(Q);
    ok_ = lu_.info() == Eigen::Success;
  }
  bool ok() const { return ok_; }

  // Sets up the energy inner product of apply_inner for the current shift: its
  // stiffness K_B is the Hermitian part of K plus a little mass, so that rigid-body
  // motion has a positive norm. Only the Arnoldi factorisations that use it call it.
  void prepare_inner() {
    Real ratio = 0.0;
    for (Index i = 0; i < n_; ++i)
      if (std::abs(M_.coeff(i, i)) > 0.0) ratio = std::max(ratio, std::abs(K_.coeff(i, i)) / std::abs(M_.coeff(i, i)));
    const Real s = std::max(std::norm(sigma_), 1e-10 * ratio);
    KB_ = Sparse(0.5 * (K_ + Sparse(K_.adjoint()))) + s * M_;
    // An axisymmetric rotor's complex-form K_B and M are real: applied to the real
    // and imaginary parts at once (real_times_complex), half the work.
    real_inner_ = false;
    if constexpr (!std::is_same_v<S, Real>) {
      auto real_part = [](const Sparse& A, SparseMatrix& out) {
        for (Index k = 0; k < A.nonZeros(); ++k)
          if (A.valuePtr()[k].imag() != 0.0) return false;
        out = A.real();
        return true;
      };
      real_inner_ = real_part(KB_, KBr_) && real_part(M_, Mr_);
    }
  }

  // y = B·x with B = diag(K_B, M): for an undamped rotor (K symmetric, D = ΩG skew)
  // the state operator is skew-adjoint in this energy inner product, and its shift
  // inverse nearly normal, so Arnoldi behaves like Lanczos — no spurious Ritz values
  // in the gaps of the spectrum, which the Euclidean inner product produces.
  void apply_inner(const Scalar* x_in, Scalar* y_out) const {
    if constexpr (!std::is_same_v<S, Real>) {
      if (real_inner_) {
        real_times_complex(KBr_, x_in, y_out);
        real_times_complex(Mr_, x_in + n_, y_out + n_);
        return;
      }
    }
    Eigen::Map<const Vec> x1(x_in, n_), x2(x_in + n_, n_);
    Eigen::Map<Vec> y1(y_out, n_), y2(y_out + n_, n_);
    y1.noalias() = KB_ * x1;
    y2.noalias() = M_ * x2;
  }

  void perform_op(const Scalar* x_in, Scalar* y_out) const {
    Eigen::Map<const Vec> x1(x_in, n_), x2(x_in + n_, n_);
    Eigen::Map<Vec> y1(y_out, n_), y2(y_out + n_, n_);
    rhs_.noalias() = M_ * x2;
    rhs_.noalias() += DsM_ * x1;
    y1 = lu_.solve(-rhs_);
    y2 = x1 + sigma_ * y1;
  }

 private:
  const Sparse& M_;
  const Sparse& D_;
  const Sparse& K_;
  Index n_;
  Scalar sigma_ = 0.0;
  Sparse DsM_, KB_;
  SparseMatrix KBr_, Mr_;  // real K_B and M, when they are (complex form)
  bool real_inner_ = false;
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu_;
  bool ok_ = false;
  mutable Vec rhs_;
};

// The state vectors of the Ritz pairs (and their values θ) of the eigenvalues of
// the shift-inverted operator largest in magnitude, from an unrestarted Arnoldi
// factorisation that grows until they have converged.
struct RitzPairs {
  Eigen::VectorXcd values;   // θ
  Eigen::MatrixXcd vectors;  // the displacement part of each Ritz vector
  Index operations = 0;      // operator applications
  bool converged = false;

  // The eigenvalues p = σ + 1/θ of the problem shift-inverted at σ.
  Eigen::VectorXcd eigenvalues(Real sigma) const {
    return values.unaryExpr([sigma](const Complex& t) { return Complex(sigma) + 1.0 / t; });
  }
};

// Arnoldi without restarts, orthogonalised by classical Gram–Schmidt with one
// selective reorthogonalisation (DGKS: "twice is enough"). The factorisation
// starts at about two vectors per wanted eigenvalue and grows by half the wanted
// count until the first @p n_required of the @p nev eigenvalues of largest |θ| (with
// any conjugate at the cut) have converged; the converged ones among all nev are
// returned — residual |β·e_mᵀy| ≤ tol·|θ|, the criterion of Spectra's
// restarted solver — or the subspace reaches @p max_size (not converged: the caller
// falls back to the restarted solver or the real form). With @p energy_inner_product
// the basis is orthonormal in the operator's energy inner product (apply_inner; the
// caller has called prepare_inner), otherwise in the Euclidean one. Deterministic:
// a fixed start vector.
template <class S>
RitzPairs growing_arnoldi(const StateShiftInvert<S>& op, Index nev, Index n_required, Index max_size, Real tol,
                          bool energy_inner_product) {
  using Mat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  const Index N = op.rows();
  RitzPairs out;
  max_size = std::min(max_size, N);
  Mat V(N, max_size + 1);
  Mat H = Mat::Zero(max_size + 1, max_size);
  // Fixed pseudo-random start vector (a linear congruential sequence).
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (Index i = 0; i < N; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    V(i, 0) = static_cast<Real>(state >> 11) * 0x1.0p-53 - 0.5;
  }
  Vec w(N), z(N), h(max_size), h2(max_size);
  // Norms and inner products in the operator's energy inner product ⟨x, y⟩ = xᴴB·y.
  auto b_norm = [&](const Vec& x, Vec& bx) {
    if (energy_inner_product)
      op.apply_inner(x.data(), bx.data());
    else
      bx = x;
    return std::sqrt(std::max(std::real(x.dot(bx)), 0.0));
  };
  {
    const Vec v0 = V.col(0);
    const Real norm0 = b_norm(v0, z);
    if (!(norm0 > 0.0)) return out;
    V.col(0) /= norm0;
  }
  Index m = 0;
  Index check_at = std::min(max_size, std::max<Index>(2 * nev + 1, 20));
  const Index growth = std::max<Index>(nev / 2, 8);
  while (m < max_size) {
    op.perform_op(V.col(m).data(), w.data());
    ++out.operations;
    const Index k = m + 1;
    if (energy_inner_product)
      op.apply_inner(w.data(), z.data());
    else
      z = w;
    const Real wbw = std::real(w.dot(z));  // ‖w‖² before orthogonalisation (z = B·w)
    h.head(k).noalias() = V.leftCols(k).adjoint() * z;
    w.noalias() -= V.leftCols(k) * h.head(k);
    // ‖w‖ after it by Pythagoras, ‖w‖² − ‖h‖², saves applying B again: where no second
    // pass is needed (‖w‖² ≥ ‖h‖²/2) its relative error is at most about 3ε.
    const Real hh = h.head(k).squaredNorm();
    Real beta = wbw - hh >= 0.514 * hh ? std::sqrt(wbw - hh) : b_norm(w, z);
    // A second pass where cancellation may have cost orthogonality (the DGKS
    // criterion ‖w‖ < ‖h‖/√2); then the basis is orthogonal to working precision.
    if (beta < 0.717 * std::sqrt(hh)) {
      h2.head(k).noalias() = V.leftCols(k).adjoint() * z;
      w.noalias() -= V.leftCols(k) * h2.head(k);
      h.head(k) += h2.head(k);
      beta = b_norm(w, z);
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

    Eigen::VectorXcd theta;
    Eigen::MatrixXcd Y;  // unit columns
    if constexpr (std::is_same_v<S, Real>) {
      const Eigen::EigenSolver<Mat> es(H.topLeftCorner(m, m));
      if (es.info() != Eigen::Success) return out;
      theta = es.eigenvalues();
      Y = es.eigenvectors();
    } else {
      const Eigen::ComplexEigenSolver<Mat> es(H.topLeftCorner(m, m));
      if (es.info() != Eigen::Success) return out;
      theta = es.eigenvalues();
      Y = es.eigenvectors();
      Y.colwise().normalize();
    }
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
    std::vector<Index> done;  // converged, among the first `take`
    bool all = true;
    for (Index c = 0; c < take; ++c) {
      const Index i = order[static_cast<std::size_t>(c)];
      const Real residual = invariant ? 0.0 : beta * std::abs(Y(m - 1, i));
      const bool ok = residual <= tol * std::max(std::abs(theta(i)), 1e-300);
      if (ok) done.push_back(i);
      if (c < n_required) all = all && ok;
    }
    if (!all && !invariant) continue;
    out.converged = true;
    const auto kept = static_cast<Index>(done.size());
    out.values.resize(kept);
    out.vectors.resize(N / 2, kept);
    for (Index c = 0; c < kept; ++c) {
      const Index i = done[static_cast<std::size_t>(c)];
      out.values(c) = theta(i);
      out.vectors.col(c) = V.topLeftCorner(N / 2, m).template cast<Complex>() * Y.col(i);
    }
    return out;
  }
  return out;
}

// Sets the shift σ of @p op; false, with the reason in @p info, when
// K + σD + σ²M is singular there.
template <class S>
bool set_shift_or_fail(StateShiftInvert<S>& op, Real sigma, SolverInfo& info) {
  op.set_shift(sigma);
  if (op.ok()) return true;
  info.fail(SolverStatus::numerical_failure, fmt::format("K + σD + σ²M is singular at the shift σ = {} rad/s", sigma));
  return false;
}

}  // namespace feran::detail
