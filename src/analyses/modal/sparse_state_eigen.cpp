#include "state_eigen.hpp"

#include <algorithm>

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
  Spectra::GenEigsRealShiftSolver<StateShiftInvert> solver(op, nev, ncv, sigma);
  if (!op.ok()) {
    out.info.converged = false;
    out.info.message = fmt::format("K + σD + σ²M is singular at the shift σ = {} rad/s", sigma);
    return out;
  }
  solver.init();
  const Index n_conv = solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10,
                                      Spectra::SortRule::LargestMagn);
  out.info.iterations = solver.num_iterations();
  out.info.n_converged = n_conv;
  if (solver.info() != Spectra::CompInfo::Successful) {
    out.info.converged = false;
    out.info.message = fmt::format("Arnoldi iteration converged {} of {} eigenvalues", n_conv, nev);
  }
  const Eigen::VectorXcd values = solver.eigenvalues();
  const Eigen::MatrixXcd vectors = solver.eigenvectors();
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
    out.vectors.col(c) = conjugate ? Eigen::VectorXcd(vectors.col(j).head(n).conjugate())
                                   : Eigen::VectorXcd(vectors.col(j).head(n));
    const Real norm = out.vectors.col(c).norm();
    if (norm > 0) out.vectors.col(c) /= norm;
  }
  return out;
}

}  // namespace feran::detail
