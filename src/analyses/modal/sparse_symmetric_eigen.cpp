#include "state_eigen.hpp"

#include <algorithm>
#include <cmath>

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

namespace feran::detail {

namespace {

Real max_abs(const SparseMatrix& A) { return A.nonZeros() > 0 ? A.coeffs().cwiseAbs().maxCoeff() : 0.0; }

// A = Aᵀ to round-off (1e-12 of the largest entry).
bool symmetric(const SparseMatrix& A) { return max_abs(SparseMatrix(A - SparseMatrix(A.transpose()))) <= 1e-12 * max_abs(A); }

}  // namespace

std::optional<StateEigenpairs> sparse_undamped_eigen(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K,
                                                     Index n_wanted, Real sigma) {
  const Index n = M.rows();
  if (n < 3 || max_abs(D) != 0.0 || !symmetric(K) || !symmetric(M)) return std::nullopt;
  const Index nev = std::min(n_wanted, n - 2);
  if (nev < 1) return std::nullopt;
  const Index ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  // p = σ on the negative real axis is λ = −σ²: the same K + σ²M as the state
  // problem's shift-invert, positive definite below the lowest eigenvalue.
  const Real shift = -sigma * sigma;
  using Op = Spectra::SymShiftInvert<Real, Eigen::Sparse, Eigen::Sparse>;
  using BOp = Spectra::SparseSymMatProd<Real>;
  Op op(K, M);
  BOp bop(M);
  Spectra::SymGEigsShiftSolver<Op, BOp, Spectra::GEigsMode::ShiftInvert> eigs(op, bop, nev, ncv, shift);
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
  out.info.method = "shift-invert-lanczos";
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
