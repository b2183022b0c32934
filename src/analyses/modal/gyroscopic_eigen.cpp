#include "state_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Cholesky>

extern "C" {
// LAPACK: all eigenvalues and eigenvectors of a Hermitian matrix (divide and conquer).
void zheevd_(const char* jobz, const char* uplo, const int* n, std::complex<double>* a, const int* lda, double* w,
             std::complex<double>* work, const int* lwork, double* rwork, const int* lrwork, int* iwork,
             const int* liwork, int* info);
}

namespace feran::detail {

namespace {

// A = ±Aᴴ to round-off: the largest entry of A ∓ Aᴴ at most 1e-12 of A's largest
// (an exactly built model gives zero or a few ulps). Squared magnitudes: std::abs of
// a complex number is a slow hypot.
bool hermitian(const ComplexMatrix& A, Real sign) {
  const Index n = A.rows();
  Real a2 = 0.0, d2 = 0.0;
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i <= j; ++i) {
      a2 = std::max({a2, abs2(A(i, j)), abs2(A(j, i))});
      d2 = std::max(d2, abs2(A(i, j) - sign * std::conj(A(j, i))));
    }
  return d2 <= tolerance::symmetry * tolerance::symmetry * a2;
}

}  // namespace

std::optional<StateEigenpairs> dense_gyroscopic_eigen(const ComplexMatrix& M, const ComplexMatrix& D,
                                                      const ComplexMatrix& K, const DenseSelection& selection,
                                                      bool both_signs) {
  const Index n = M.rows();
  if (n == 0 || !hermitian(M, 1.0) || !hermitian(K, 1.0) || !hermitian(D, -1.0)) return std::nullopt;
  const Eigen::LLT<ComplexMatrix> lk(K), lm(M);
  if (lk.info() != Eigen::Success || lm.info() != Eigen::Success) return std::nullopt;

  // C = L⁻¹·B·L⁻ᴴ with L = diag(L_K, L_M), M = L_M·L_Mᴴ:
  //   C = [[−L_K⁻¹·H·L_K⁻ᴴ, L_K⁻¹·L_M], [L_Mᴴ·L_K⁻ᴴ, 0]]  (lower triangle used).
  const Index N = 2 * n;
  ComplexMatrix C = ComplexMatrix::Zero(N, N);
  const ComplexMatrix H = Complex(0.0, 1.0) * D;
  const ComplexMatrix X = lk.matrixL().solve(H);  // L_K⁻¹·H; Xᴴ = H·L_K⁻ᴴ
  C.topLeftCorner(n, n) = -lk.matrixL().solve(X.adjoint());
  C.bottomLeftCorner(n, n) = lk.matrixL().solve(ComplexMatrix(lm.matrixL())).adjoint();

  const int Ni = static_cast<int>(N);
  const int lwork = 2 * Ni + Ni * Ni, lrwork = 1 + 5 * Ni + 2 * Ni * Ni, liwork = 3 + 5 * Ni;
  std::vector<Complex> work(static_cast<std::size_t>(lwork));
  std::vector<Real> rwork(static_cast<std::size_t>(lrwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  Vector mu(N);
  int info = 0;
  zheevd_("V", "L", &Ni, C.data(), &Ni, mu.data(), work.data(), &lwork, rwork.data(), &lrwork, iwork.data(), &liwork,
          &info);
  if (info != 0) return std::nullopt;

  // μ = 1/ω; the lowest |ω| are the largest |μ| at both ends of the spectrum.
  std::vector<Index> order;
  for (Index j = 0; j < N; ++j) {
    if (std::abs(mu(j)) * selection.zero_tol >= 1.0) return std::nullopt;  // |ω| < zero_tol: rigid body
    if (both_signs || mu(j) > 0.0) order.push_back(j);
  }
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return std::abs(mu(a)) > std::abs(mu(b)); });
  auto keep = order.size();
  if (selection.count > 0 && static_cast<std::size_t>(selection.count) < order.size()) {
    // The partners of a repeated |ω| at the cut stay (1e-7 relative, as ModalSolver).
    keep = static_cast<std::size_t>(selection.count);
    while (keep < order.size() && std::abs(std::abs(mu(order[keep])) - std::abs(mu(order[keep - 1]))) <=
                                      tolerance::repeated_eigenvalue * std::abs(mu(order[keep])))
      ++keep;
  }

  StateEigenpairs out;
  out.info.method = SolverMethod::dense_hermitian;
  out.values.resize(static_cast<Index>(keep));
  out.vectors.resize(n, static_cast<Index>(keep));
  for (std::size_t k = 0; k < keep; ++k) {
    const Index j = order[k];
    const auto c = static_cast<Index>(k);
    out.values(c) = Complex(0.0, 1.0 / mu(j));
    // x = L_K⁻ᴴ·v_top (the displacement half of z = L⁻ᴴ·v).
    out.vectors.col(c) = lk.matrixU().solve(C.col(j).head(n));
    out.vectors.col(c).normalize();
  }
  out.info.n_converged = static_cast<Index>(keep);
  return out;
}

bool hermitian_eigen(ComplexMatrix A, Vector& values, ComplexMatrix& vectors) {
  const int n = static_cast<int>(A.rows());
  values.resize(n);
  if (n == 0) {
    vectors.resize(0, 0);
    return true;
  }
  const int lwork = 2 * n + n * n, lrwork = 1 + 5 * n + 2 * n * n, liwork = 3 + 5 * n;
  std::vector<Complex> work(static_cast<std::size_t>(lwork));
  std::vector<Real> rwork(static_cast<std::size_t>(lrwork));
  std::vector<int> iwork(static_cast<std::size_t>(liwork));
  int info = 0;
  zheevd_("V", "L", &n, A.data(), &n, values.data(), work.data(), &lwork, rwork.data(), &lrwork, iwork.data(), &liwork,
          &info);
  vectors = std::move(A);
  return info == 0;
}

}  // namespace feran::detail
