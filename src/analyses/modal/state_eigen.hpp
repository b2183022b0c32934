#pragma once
// Eigen solvers for the first-order (state-space) form of the quadratic problem
// (p²M + pD + K)φ = 0. Private to analyses/modal.

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/types.hpp>

namespace feran::detail {

struct StateEigenpairs {
  ComplexVector values;   // eigenvalues p
  ComplexMatrix vectors;  // displacement part φ of each eigenvector (n × count), unit norm
  SolverInfo info;
};

// All 2n eigenpairs of A = [[0, I], [−M⁻¹K, −M⁻¹D]] by LAPACK dgeev (balancing,
// Hessenberg reduction, shifted QR). Only eigenvalues with Im p ≥ 0 are returned.
StateEigenpairs dense_state_eigen(const Matrix& M, const Matrix& D, const Matrix& K);

// The @p n_wanted eigenvalues nearest the real shift @p sigma (and their conjugates
// dropped), by shift-invert Arnoldi: (A − σI)⁻¹ is applied through one sparse LU of
// K + σD + σ²M.
StateEigenpairs sparse_state_eigen(const SparseMatrix& M, const SparseMatrix& D,
                                   const SparseMatrix& K, Index n_wanted, Real sigma);

}  // namespace feran::detail
