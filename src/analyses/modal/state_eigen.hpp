#pragma once
// Eigen solvers for the first-order (state-space) form of the quadratic problem
// (p²M + pD + K)φ = 0. Private to analyses/modal.

#include <feran/analyses/modal/modal.hpp>
#include <feran/core/types.hpp>
#include <feran/core/tolerances.hpp>

#include <optional>

#include <Eigen/SparseCore>

namespace feran::detail {

// y = A·x for a real sparse A and complex x (both arrays of A.cols()/A.rows()
// entries): the real and imaginary parts at once, as A times the n × 2 real matrix a
// complex array is.
inline void real_times_complex(const SparseMatrix& A, const Complex* x, Complex* y) {
  using Pairs = Eigen::Matrix<Real, Eigen::Dynamic, 2, Eigen::RowMajor>;
  Eigen::Map<Pairs>(reinterpret_cast<Real*>(y), A.rows(), 2).noalias() =
      A * Eigen::Map<const Pairs>(reinterpret_cast<const Real*>(x), A.cols(), 2);
}

struct StateEigenpairs {
  ComplexVector values;   // eigenvalues p
  ComplexMatrix vectors;  // displacement part φ of each eigenvector (n × count), unit norm
  SolverInfo info;
};

// Which eigenpairs a dense solve returns vectors for: all (count = 0), or the
// @p count eigenvalues nearest the origin, counting only those with Im p > 0 when
// @p oscillatory_only, plus every eigenvalue with |p| < zero_tol (rigid-body modes,
// told apart only by their vectors) and the partners of repeated eigenvalues at
// the cut (1e-7 relative, as ModalSolver keeps pairs whole).
struct DenseSelection {
  Index count = 0;
  bool oscillatory_only = false;
  Real zero_tol = 0.0;
};

// Eigenpairs of A = [[0, I], [−M⁻¹K, −M⁻¹D]] with Im p ≥ 0. All of them: LAPACK
// dgeev (balancing, Hessenberg reduction, shifted QR, vectors from the Schur form).
// A selection: the same balancing, reduction and QR for the eigenvalues only
// (dhseqr), then the selected vectors by inverse iteration on the Hessenberg form
// (dhsein), which is several times cheaper when few modes are wanted. Repeated
// eigenvalues among the selected fall back to dgeev: inverse iteration does not give
// a well-conditioned basis of a multiple eigenvalue's eigenspace.
StateEigenpairs dense_state_eigen(const Matrix& M, const Matrix& D, const Matrix& K,
                                  const DenseSelection& selection = {});

// Convergence tolerance of the shift-inverted eigenvalues in every Krylov solver
// (Spectra's test, relative).
constexpr Real arnoldi_tolerance = 1e-10;

// Size of the Krylov subspace sparse_state_eigen builds for @p n_wanted modes of a
// system with @p n DOF (at most the state dimension 2n).
Index arnoldi_subspace_size(Index n, Index n_wanted);

// The @p n_wanted eigenvalues nearest the real shift @p sigma (and their conjugates
// dropped), by shift-invert Arnoldi: (A − σI)⁻¹ is applied through one sparse LU of
// K + σD + σ²M. An unrestarted factorisation grows until the wanted eigenvalues
// converge (usually well below arnoldi_subspace_size); Spectra's implicitly
// restarted solver takes over when they have not within that size.
StateEigenpairs sparse_state_eigen(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K, Index n_wanted,
                                   Real sigma);

// The complex form of an axisymmetric rotor's lateral motion: with M, D, K commuting
// with the quarter turn J about the spin axis, the real problem splits into the
// invariant subspaces J·x = ±i·x, complex conjugates of each other. The half-size
// complex problem (p²Mc + pDc + Kc)y = 0 on J·x = i·x (Mc Hermitian positive
// definite) has one eigenvalue per mode — forward whirl on one side of the real axis,
// backward on the other — where the real problem has a conjugate pair. The solver
// returns its eigenpairs (all signs of Im p), y of unit norm; ModalSolver maps them
// back to real coordinates.
using ComplexSparseMatrix = Eigen::SparseMatrix<Complex>;

// Dense, as dense_state_eigen: all eigenpairs (zgeev), or those @p selection picks
// (counting |p| of the mode, Im p of either sign) by balancing, Hessenberg QR for
// the eigenvalues (zhseqr) and inverse iteration for the selected vectors (zhsein);
// a repeated eigenvalue among the selected falls back to zgeev.
StateEigenpairs dense_complex_eigen(const ComplexMatrix& M, const ComplexMatrix& D, const ComplexMatrix& K,
                                    const DenseSelection& selection = {});

// The @p n_wanted eigenvalues nearest the real shift @p sigma by shift-invert
// Arnoldi grown until they converge (complex sparse LU of K + σD + σ²M); not
// converged within three vectors per eigenvalue → info.status = not_converged.
StateEigenpairs sparse_complex_eigen(const ComplexSparseMatrix& M, const ComplexSparseMatrix& D,
                                     const ComplexSparseMatrix& K, Index n_wanted, Real sigma);

/// All eigenvalues (ascending) and orthonormal eigenvectors of the Hermitian matrix
/// @p A (its lower triangle is used), by LAPACK's zheevd; false when it did not converge.
bool hermitian_eigen(ComplexMatrix A, Vector& values, ComplexMatrix& vectors);

// A conservative gyroscopic problem — M and K Hermitian positive definite, D
// skew-Hermitian (gyroscopic terms only: no damping, no circulatory stiffness) — has
// its eigenvalues on the imaginary axis, p = iω, and with H = iD Hermitian,
// (−ω²M + ωH + K)x = 0. Linearised with z = (x, ωx) as the Hermitian-definite pencil
// B·z = (1/ω)·A·z, A = diag(K, M) > 0, B = [[−H, M], [M, 0]], it is solved by a
// Cholesky factorisation of A and LAPACK's Hermitian eigensolver (zheevd): several
// times cheaper than the Hessenberg QR of the state matrix, and backward stable for
// the quadratic problem (real eigenvalues, orthogonal eigenvectors, no spurious
// damping from round-off). Returns the pairs @p selection picks — counting both
// signs of ω when @p both_signs (the complex form, where ω < 0 is a backward mode),
// otherwise only ω > 0 (the real form, where −ω is the conjugate) — with Re p = 0
// exactly; std::nullopt when the problem is not of this kind: M, D or K not of that
// symmetry to round-off (1e-12 of the largest entry), K or M not positive definite,
// or an |ω| below selection.zero_tol (a rigid-body mode: K is singular).
std::optional<StateEigenpairs> dense_gyroscopic_eigen(const ComplexMatrix& M, const ComplexMatrix& D,
                                                      const ComplexMatrix& K, const DenseSelection& selection,
                                                      bool both_signs);

// A block without damping and gyroscopic terms (D = 0; M, K symmetric to 1e-12):
// (K − ω²M)x = 0, a symmetric-definite problem of order n instead of the state
// problem's 2n. The @p n_wanted lowest ω by Spectra's shift-invert Lanczos on
// (K + σ²M)⁻¹M (λ = −σ² is the state shift σ), returned as p = iω, x real of unit
// norm. std::nullopt when the block is not of this kind, when Lanczos does not
// converge, or when some λ is negative beyond round-off (a static divergence, p real:
// the general solver's case).
std::optional<StateEigenpairs> sparse_undamped_eigen(const SparseMatrix& M, const SparseMatrix& D,
                                                     const SparseMatrix& K, Index n_wanted, Real sigma);

}  // namespace feran::detail
