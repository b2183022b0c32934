#include "state_eigen.hpp"

#include <Eigen/Cholesky>

extern "C" {
// LAPACK: eigenvalues and right eigenvectors of a real general matrix.
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda,
            double* wr, double* wi, double* vl, const int* ldvl, double* vr, const int* ldvr,
            double* work, const int* lwork, int* info);
}

namespace feran::detail {

StateEigenpairs dense_state_eigen(const Matrix& M, const Matrix& D, const Matrix& K) {
  const Index n = M.rows();
  StateEigenpairs out;
  out.info.method = "dense-qr";
  if (n == 0) return out;

  const Eigen::LLT<Matrix> llt(M);
  Matrix A = Matrix::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -llt.solve(K);
  A.bottomRightCorner(n, n) = -llt.solve(D);

  const int N = static_cast<int>(2 * n);
  Vector wr(N), wi(N);
  Matrix vr(N, N);
  double vl_dummy = 0.0;
  const int one = 1;
  int info = 0, lwork = -1;
  double work_query = 0.0;
  dgeev_("N", "V", &N, A.data(), &N, wr.data(), wi.data(), &vl_dummy, &one, vr.data(), &N,
         &work_query, &lwork, &info);
  lwork = static_cast<int>(work_query);
  Vector work(lwork);
  dgeev_("N", "V", &N, A.data(), &N, wr.data(), wi.data(), &vl_dummy, &one, vr.data(), &N,
         work.data(), &lwork, &info);
  if (info != 0) {
    out.info.converged = false;
    out.info.message = info > 0 ? "the QR algorithm did not converge (LAPACK dgeev info > 0)"
                                : "invalid argument to LAPACK dgeev";
    return out;
  }

  // dgeev stores a complex pair (wi > 0 first) as columns j (real part) and j+1 (imaginary).
  std::vector<Index> keep;
  for (Index j = 0; j < N; ++j)
    if (wi(j) >= 0.0) keep.push_back(j);
  out.values.resize(static_cast<Index>(keep.size()));
  out.vectors.resize(n, static_cast<Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const Index j = keep[k];
    const auto c = static_cast<Index>(k);
    out.values(c) = Complex(wr(j), wi(j));
    if (wi(j) > 0.0)
      out.vectors.col(c) = vr.col(j).head(n).cast<Complex>() + Complex(0, 1) * vr.col(j + 1).head(n).cast<Complex>();
    else
      out.vectors.col(c) = vr.col(j).head(n).cast<Complex>();
    const Real norm = out.vectors.col(c).norm();
    if (norm > 0) out.vectors.col(c) /= norm;
  }
  out.info.n_converged = static_cast<Index>(keep.size());
  return out;
}

}  // namespace feran::detail
