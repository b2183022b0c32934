#include "state_eigen.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

namespace feran::detail {

namespace {

Real max_abs(const SparseMatrix& A) { return A.nonZeros() > 0 ? A.coeffs().cwiseAbs().maxCoeff() : 0.0; }

// A = Aᵀ to round-off (1e-12 of the largest entry).
bool symmetric(const SparseMatrix& A) {
  return max_abs(SparseMatrix(A - SparseMatrix(A.transpose()))) <= tolerance::symmetry * max_abs(A);
}

// y = (K − s·M)⁻¹x for Spectra, by a sparse LDLᵀ: below the lowest eigenvalue the
// matrix is positive definite (Spectra's own operator uses a general sparse LU).
class ShiftInvertLdlt {
 public:
  using Scalar = Real;
  ShiftInvertLdlt(const SparseMatrix& K, const SparseMatrix& M) : K_(K), M_(M) {}
  Index rows() const { return K_.rows(); }
  Index cols() const { return K_.cols(); }
  void set_shift(Real s) {
    ldlt_.compute(SparseMatrix(K_ - s * M_));
    ok_ = ldlt_.info() == Eigen::Success && (ldlt_.vectorD().array() > 0.0).all();
  }
  bool ok() const { return ok_; }
  void perform_op(const Real* x_in, Real* y_out) const {
    Eigen::Map<Vector>(y_out, K_.rows()) = ldlt_.solve(Eigen::Map<const Vector>(x_in, K_.rows()));
  }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
  bool ok_ = false;
};

}  // namespace

std::optional<StateEigenpairs> sparse_undamped_eigen(const SparseMatrix& M, const SparseMatrix& D,
                                                     const SparseMatrix& K, Index n_wanted, Real sigma) {
  const Index n = M.rows();
  if (n < 3 || max_abs(D) != 0.0 || !symmetric(K) || !symmetric(M)) return std::nullopt;
  const Index nev = std::min(n_wanted, n - 2);
  if (nev < 1) return std::nullopt;
  const Index ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  // p = σ on the negative real axis is λ = −σ²: the same K + σ²M as the state
  // problem's shift-invert, positive definite below the lowest eigenvalue.
  const Real shift = -sigma * sigma;
  using BOp = Spectra::SparseSymMatProd<Real>;
  ShiftInvertLdlt op(K, M);
  BOp bop(M);
  Spectra::SymGEigsShiftSolver<ShiftInvertLdlt, BOp, Spectra::GEigsMode::ShiftInvert> eigs(op, bop, nev, ncv, shift);
  if (!op.ok()) return std::nullopt;
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, arnoldi_tolerance);
  if (eigs.info() != Spectra::CompInfo::Successful) return std::nullopt;
  const Vector lambda = eigs.eigenvalues();
  const Matrix X = eigs.eigenvectors();
  // A negative λ beyond round-off (of the largest one found, 1e-10) is a divergent
  // static mode, p real: left to the general solver. Round-off below zero is a
  // rigid-body motion, p = 0.
  const Real scale = std::max(lambda.cwiseAbs().maxCoeff(), std::abs(shift));
  if (lambda.minCoeff() < -1e-10 * scale) return std::nullopt;

  StateEigenpairs out;
  out.info.method = SolverMethod::shift_invert_lanczos;
  out.info.iterations = eigs.num_iterations();
  out.values.resize(lambda.size());
  out.vectors.resize(n, lambda.size());
  for (Index j = 0; j < lambda.size(); ++j) {
    out.values(j) = Complex(0.0, std::sqrt(std::max(lambda(j), 0.0)));
    out.vectors.col(j) = X.col(j).normalized().cast<Complex>();
  }
  out.info.n_converged = lambda.size();
  return out;
}

}  // namespace feran::detail
