#include "state_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include <Eigen/Cholesky>

extern "C" {
// LAPACK: eigenvalues and right eigenvectors of a real general matrix.
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr, double* wi,
            double* vl, const int* ldvl, double* vr, const int* ldvr, double* work, const int* lwork, int* info);
// LAPACK: the steps of dgeev, for eigenvalues first and selected vectors after.
void dgebal_(const char* job, const int* n, double* a, const int* lda, int* ilo, int* ihi, double* scale, int* info);
void dgehrd_(const int* n, const int* ilo, const int* ihi, double* a, const int* lda, double* tau, double* work,
             const int* lwork, int* info);
void dhseqr_(const char* job, const char* compz, const int* n, const int* ilo, const int* ihi, double* h,
             const int* ldh, double* wr, double* wi, double* z, const int* ldz, double* work, const int* lwork,
             int* info);
void dhsein_(const char* side, const char* eigsrc, const char* initv, int* select, const int* n, const double* h,
             const int* ldh, double* wr, const double* wi, double* vl, const int* ldvl, double* vr, const int* ldvr,
             const int* mm, int* m, double* work, int* ifaill, int* ifailr, int* info);
void dormhr_(const char* side, const char* trans, const int* m, const int* n, const int* ilo, const int* ihi,
             const double* a, const int* lda, const double* tau, double* c, const int* ldc, double* work,
             const int* lwork, int* info);
void dgebak_(const char* job, const char* side, const int* n, const int* ilo, const int* ihi, const double* scale,
             const int* m, double* v, const int* ldv, int* info);
// The same steps for a complex general matrix.
void zgeev_(const char* jobvl, const char* jobvr, const int* n, std::complex<double>* a, const int* lda,
            std::complex<double>* w, std::complex<double>* vl, const int* ldvl, std::complex<double>* vr,
            const int* ldvr, std::complex<double>* work, const int* lwork, double* rwork, int* info);
void zgebal_(const char* job, const int* n, std::complex<double>* a, const int* lda, int* ilo, int* ihi, double* scale,
             int* info);
void zgehrd_(const int* n, const int* ilo, const int* ihi, std::complex<double>* a, const int* lda,
             std::complex<double>* tau, std::complex<double>* work, const int* lwork, int* info);
void zhseqr_(const char* job, const char* compz, const int* n, const int* ilo, const int* ihi, std::complex<double>* h,
             const int* ldh, std::complex<double>* w, std::complex<double>* z, const int* ldz,
             std::complex<double>* work, const int* lwork, int* info);
void zhsein_(const char* side, const char* eigsrc, const char* initv, const int* select, const int* n,
             const std::complex<double>* h, const int* ldh, std::complex<double>* w, std::complex<double>* vl,
             const int* ldvl, std::complex<double>* vr, const int* ldvr, const int* mm, int* m,
             std::complex<double>* work, double* rwork, int* ifaill, int* ifailr, int* info);
void zunmhr_(const char* side, const char* trans, const int* m, const int* n, const int* ilo, const int* ihi,
             const std::complex<double>* a, const int* lda, const std::complex<double>* tau, std::complex<double>* c,
             const int* ldc, std::complex<double>* work, const int* lwork, int* info);
void zgebak_(const char* job, const char* side, const int* n, const int* ilo, const int* ihi, const double* scale,
             const int* m, std::complex<double>* v, const int* ldv, int* info);

// LAPACK's error handler, called with the routine's name and the position of an
// illegal argument before the routine returns info < 0. OpenBLAS's (a weak symbol,
// meant to be replaced) prints "** On entry to … had an illegal value" on standard
// output, the reference one stops the program: feran's library neither prints nor
// exits, and every caller checks info and reports the failure itself. Defined here,
// in the object that calls LAPACK, so that every program linking the dense solvers
// links this handler too.
void xerbla_(const char* /*name*/, const int* /*info*/, std::size_t /*name_length*/) {}
}

namespace feran::detail {

namespace {

// Repeated when equal to 1e-7 relative (the criterion of ModalSolver, which
// re-splits such clusters and keeps them whole).
bool repeated(Complex a, Complex b) {
  return magnitude(a - b) <= tolerance::repeated_eigenvalue * std::max(magnitude(a), 1e-300);
}

Matrix state_matrix(const Matrix& M, const Matrix& D, const Matrix& K) {
  const Index n = M.rows();
  const Eigen::LLT<Matrix> llt(M);
  Matrix A = Matrix::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -llt.solve(K);
  A.bottomRightCorner(n, n) = -llt.solve(D);
  return A;
}

// Appends eigenvalue p with the displacement part (first n rows) of the real vector
// in column j of @p v, or of the complex one in columns j (real) and j + 1 (imaginary).
void append(StateEigenpairs& out, Index k, Complex p, const Matrix& v, Index j, bool complex_pair) {
  const Index n = out.vectors.rows();
  out.values(k) = p;
  if (complex_pair)
    out.vectors.col(k) = v.col(j).head(n).cast<Complex>() + Complex(0, 1) * v.col(j + 1).head(n).cast<Complex>();
  else
    out.vectors.col(k) = v.col(j).head(n).cast<Complex>();
  const Real norm = out.vectors.col(k).norm();
  if (norm > 0) out.vectors.col(k) /= norm;
}

void fail(StateEigenpairs& out, const char* routine, int info) {
  out.info.status = info > 0 ? SolverStatus::not_converged : SolverStatus::numerical_failure;
  out.info.message = info > 0 ? std::string("the QR algorithm did not converge (LAPACK ") + routine + " info > 0)"
                              : std::string("invalid argument to LAPACK ") + routine;
}

// All eigenpairs with Im p ≥ 0 by dgeev.
StateEigenpairs all_pairs(Matrix A, Index n) {
  StateEigenpairs out;
  out.info.method = SolverMethod::dense_qr;
  const int N = static_cast<int>(A.rows());
  Vector wr(N), wi(N);
  Matrix vr(N, N);
  double vl_dummy = 0.0;
  const int one = 1;
  int info = 0, lwork = -1;
  double work_query = 0.0;
  dgeev_("N", "V", &N, A.data(), &N, wr.data(), wi.data(), &vl_dummy, &one, vr.data(), &N, &work_query, &lwork, &info);
  lwork = static_cast<int>(work_query);
  Vector work(lwork);
  dgeev_("N", "V", &N, A.data(), &N, wr.data(), wi.data(), &vl_dummy, &one, vr.data(), &N, work.data(), &lwork, &info);
  if (info != 0) {
    fail(out, "dgeev", info);
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
    append(out, static_cast<Index>(k), Complex(wr(j), wi(j)), vr, j, wi(j) > 0.0);
  }
  out.info.n_converged = static_cast<Index>(keep.size());
  return out;
}

// The eigenvalues (Im p ≥ 0) that @p s selects, as indices into wr/wi; empty when a
// repeated eigenvalue is among them.
std::vector<Index> select_pairs(const Vector& wr, const Vector& wi, const DenseSelection& s, bool& has_repeated) {
  std::vector<Index> order;
  for (Index j = 0; j < wr.size(); ++j)
    if (wi(j) >= 0.0) order.push_back(j);
  auto p = [&](Index j) { return Complex(wr(j), wi(j)); };
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return magnitude(p(a)) < magnitude(p(b)); });
  std::vector<Index> chosen;
  Index counted = 0;
  Complex last;
  for (Index j : order) {
    const Complex pj = p(j);
    if (magnitude(pj) < s.zero_tol) {
      chosen.push_back(j);
      continue;
    }
    const bool counts = !s.oscillatory_only || wi(j) > 0.0;
    // A real positive eigenvalue (divergence) is kept wherever it lies, so that the
    // stability of a sweep of oscillatory modes still sees it.
    const bool divergent = s.oscillatory_only && wi(j) == 0.0 && wr(j) > 0.0;
    if (counted >= s.count) {
      if ((counts && repeated(pj, last)) || divergent) chosen.push_back(j);
      continue;
    }
    if (!counts) {
      if (divergent) chosen.push_back(j);
      continue;
    }
    chosen.push_back(j);
    ++counted;
    last = pj;
  }
  has_repeated = false;
  for (std::size_t a = 0; a < chosen.size(); ++a)
    for (std::size_t b = a + 1; b < chosen.size(); ++b)
      has_repeated = has_repeated || repeated(p(chosen[a]), p(chosen[b]));
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// The complex problem's counterparts. A complex eigenvalue w is the mode with
// eigenvalue q = w or its conjugate, whichever has Im q ≥ 0: selection and
// repetition are judged on q.
Complex mode_value(Complex w) { return w.imag() >= 0.0 ? w : std::conj(w); }

ComplexMatrix complex_state_matrix(const ComplexMatrix& M, const ComplexMatrix& D, const ComplexMatrix& K) {
  const Index n = M.rows();
  const Eigen::LLT<ComplexMatrix> llt(M);
  ComplexMatrix A = ComplexMatrix::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -llt.solve(K);
  A.bottomRightCorner(n, n) = -llt.solve(D);
  return A;
}

StateEigenpairs all_complex_pairs(ComplexMatrix A, Index n) {
  StateEigenpairs out;
  out.info.method = SolverMethod::dense_qr;
  const int N = static_cast<int>(A.rows());
  ComplexVector w(N);
  ComplexMatrix vr(N, N);
  Complex vl_dummy = 0.0;
  const int one = 1;
  int info = 0, lwork = -1;
  Complex query = 0.0;
  Vector rwork(2 * N);
  zgeev_("N", "V", &N, A.data(), &N, w.data(), &vl_dummy, &one, vr.data(), &N, &query, &lwork, rwork.data(), &info);
  lwork = static_cast<int>(query.real());
  ComplexVector work(lwork);
  zgeev_("N", "V", &N, A.data(), &N, w.data(), &vl_dummy, &one, vr.data(), &N, work.data(), &lwork, rwork.data(),
         &info);
  if (info != 0) {
    fail(out, "zgeev", info);
    return out;
  }
  out.values = w;
  out.vectors = vr.topRows(n);
  out.vectors.colwise().normalize();
  out.info.n_converged = N;
  return out;
}

std::vector<Index> select_complex(const ComplexVector& w, const DenseSelection& s, bool& has_repeated) {
  std::vector<Index> order;
  for (Index j = 0; j < w.size(); ++j) order.push_back(j);
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return magnitude(w(a)) < magnitude(w(b)); });
  std::vector<Index> chosen;
  Index counted = 0;
  Complex last;
  for (Index j : order) {
    const Complex q = mode_value(w(j));
    if (magnitude(q) < s.zero_tol) {
      chosen.push_back(j);
      continue;
    }
    const bool counts = !s.oscillatory_only || q.imag() > 0.0;
    const bool divergent = s.oscillatory_only && q.imag() == 0.0 && q.real() > 0.0;
    if (counted >= s.count) {
      if ((counts && repeated(q, last)) || divergent) chosen.push_back(j);
      continue;
    }
    if (!counts) {
      if (divergent) chosen.push_back(j);
      continue;
    }
    chosen.push_back(j);
    ++counted;
    last = q;
  }
  has_repeated = false;
  for (std::size_t a = 0; a < chosen.size(); ++a)
    for (std::size_t b = a + 1; b < chosen.size(); ++b)
      has_repeated = has_repeated || repeated(mode_value(w(chosen[a])), mode_value(w(chosen[b])));
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

}  // namespace

StateEigenpairs dense_complex_eigen(const ComplexMatrix& M, const ComplexMatrix& D, const ComplexMatrix& K,
                                    const DenseSelection& selection) {
  const Index n = M.rows();
  StateEigenpairs out;
  out.info.method = SolverMethod::dense_qr;
  if (n == 0) return out;
  const ComplexMatrix A0 = complex_state_matrix(M, D, K);
  if (selection.count <= 0 || selection.count >= n) return all_complex_pairs(A0, n);

  ComplexMatrix A = A0;
  const int N = static_cast<int>(2 * n);
  int ilo = 1, ihi = N, info = 0;
  Vector scale(N);
  zgebal_("B", &N, A.data(), &N, &ilo, &ihi, scale.data(), &info);
  ComplexVector tau(std::max(N - 1, 1));
  int lwork = -1;
  Complex query = 0.0;
  zgehrd_(&N, &ilo, &ihi, A.data(), &N, tau.data(), &query, &lwork, &info);
  ComplexVector work(std::max(static_cast<int>(query.real()), (N + 2) * N));
  lwork = static_cast<int>(work.size());
  zgehrd_(&N, &ilo, &ihi, A.data(), &N, tau.data(), work.data(), &lwork, &info);
  if (info != 0) return all_complex_pairs(A0, n);
  ComplexMatrix H = A;
  for (Index j = 0; j < N; ++j)
    for (Index i = j + 2; i < N; ++i) H(i, j) = 0.0;

  ComplexMatrix T = H;
  ComplexVector w(N);
  Complex z_dummy = 0.0;
  const int one = 1;
  zhseqr_("E", "N", &N, &ilo, &ihi, T.data(), &N, w.data(), &z_dummy, &one, work.data(), &lwork, &info);
  if (info != 0) return all_complex_pairs(A0, n);

  bool has_repeated = false;
  const std::vector<Index> chosen = select_complex(w, selection, has_repeated);
  if (has_repeated) return all_complex_pairs(A0, n);

  std::vector<int> select(static_cast<std::size_t>(N), 0);
  for (Index j : chosen) select[static_cast<std::size_t>(j)] = 1;
  const int mm = std::max(static_cast<int>(chosen.size()), 1);
  ComplexMatrix V(N, mm);
  ComplexVector w_work = w;  // zhsein may perturb close eigenvalues
  std::vector<int> ifaill(static_cast<std::size_t>(mm)), ifailr(ifaill.size());
  Vector rwork(N);
  Complex vl_dummy = 0.0;
  int m = 0;
  zhsein_("R", "Q", "N", select.data(), &N, H.data(), &N, w_work.data(), &vl_dummy, &one, V.data(), &N, &mm, &m,
          work.data(), rwork.data(), ifaill.data(), ifailr.data(), &info);
  if (info != 0) return all_complex_pairs(A0, n);
  lwork = -1;
  zunmhr_("L", "N", &N, &m, &ilo, &ihi, A.data(), &N, tau.data(), V.data(), &N, &query, &lwork, &info);
  if (static_cast<Index>(query.real()) > work.size()) work.resize(static_cast<Index>(query.real()));
  lwork = static_cast<int>(work.size());
  zunmhr_("L", "N", &N, &m, &ilo, &ihi, A.data(), &N, tau.data(), V.data(), &N, work.data(), &lwork, &info);
  zgebak_("B", "R", &N, &ilo, &ihi, scale.data(), &m, V.data(), &N, &info);

  out.values.resize(static_cast<Index>(chosen.size()));
  out.vectors.resize(n, static_cast<Index>(chosen.size()));
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const auto c = static_cast<Index>(k);
    out.values(c) = w(chosen[k]);
    out.vectors.col(c) = V.col(c).head(n).normalized();
  }
  out.info.n_converged = static_cast<Index>(chosen.size());
  return out;
}

StateEigenpairs dense_state_eigen(const Matrix& M, const Matrix& D, const Matrix& K, const DenseSelection& selection) {
  const Index n = M.rows();
  StateEigenpairs out;
  out.info.method = SolverMethod::dense_qr;
  if (n == 0) return out;
  const Matrix A0 = state_matrix(M, D, K);
  if (selection.count <= 0 || selection.count >= n) return all_pairs(A0, n);

  // Balance and reduce to Hessenberg form H = Qᵀ·A_bal·Q (Q kept as reflectors in A).
  Matrix A = A0;
  const int N = static_cast<int>(2 * n);
  int ilo = 1, ihi = N, info = 0;
  Vector scale(N);
  dgebal_("B", &N, A.data(), &N, &ilo, &ihi, scale.data(), &info);
  Vector tau(std::max(N - 1, 1));
  int lwork = -1;
  double query = 0.0;
  dgehrd_(&N, &ilo, &ihi, A.data(), &N, tau.data(), &query, &lwork, &info);
  Vector work(std::max(static_cast<int>(query), (N + 2) * N));
  lwork = static_cast<int>(work.size());
  dgehrd_(&N, &ilo, &ihi, A.data(), &N, tau.data(), work.data(), &lwork, &info);
  if (info != 0) return all_pairs(A0, n);
  Matrix H = A;
  for (Index j = 0; j < N; ++j)
    for (Index i = j + 2; i < N; ++i) H(i, j) = 0.0;

  // Eigenvalues only: no Schur vectors to accumulate.
  Matrix T = H;
  Vector wr(N), wi(N);
  double z_dummy = 0.0;
  const int one = 1;
  lwork = static_cast<int>(work.size());
  dhseqr_("E", "N", &N, &ilo, &ihi, T.data(), &N, wr.data(), wi.data(), &z_dummy, &one, work.data(), &lwork, &info);
  if (info != 0) return all_pairs(A0, n);

  bool has_repeated = false;
  const std::vector<Index> chosen = select_pairs(wr, wi, selection, has_repeated);
  if (has_repeated) return all_pairs(A0, n);

  // Selected right eigenvectors of H by inverse iteration, then x = D·Q·y.
  std::vector<int> select(static_cast<std::size_t>(N), 0);
  int mm = 0;
  for (Index j : chosen) {
    select[static_cast<std::size_t>(j)] = 1;
    mm += wi(j) > 0.0 ? 2 : 1;
  }
  Matrix V(N, std::max(mm, 1));
  Vector wr_work = wr;  // dhsein may perturb close eigenvalues
  std::vector<int> ifaill(static_cast<std::size_t>(std::max(mm, 1))), ifailr(ifaill.size());
  double vl_dummy = 0.0;
  int m = 0;
  dhsein_("R", "Q", "N", select.data(), &N, H.data(), &N, wr_work.data(), wi.data(), &vl_dummy, &one, V.data(), &N, &mm,
          &m, work.data(), ifaill.data(), ifailr.data(), &info);
  if (info != 0) return all_pairs(A0, n);
  lwork = -1;
  dormhr_("L", "N", &N, &m, &ilo, &ihi, A.data(), &N, tau.data(), V.data(), &N, &query, &lwork, &info);
  if (static_cast<Index>(query) > work.size()) work.resize(static_cast<Index>(query));
  lwork = static_cast<int>(work.size());
  dormhr_("L", "N", &N, &m, &ilo, &ihi, A.data(), &N, tau.data(), V.data(), &N, work.data(), &lwork, &info);
  dgebak_("B", "R", &N, &ilo, &ihi, scale.data(), &m, V.data(), &N, &info);

  out.values.resize(static_cast<Index>(chosen.size()));
  out.vectors.resize(n, static_cast<Index>(chosen.size()));
  Index col = 0;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const Index j = chosen[k];
    const bool pair = wi(j) > 0.0;
    append(out, static_cast<Index>(k), Complex(wr(j), wi(j)), V, col, pair);
    col += pair ? 2 : 1;
  }
  out.info.n_converged = static_cast<Index>(chosen.size());
  return out;
}

}  // namespace feran::detail
