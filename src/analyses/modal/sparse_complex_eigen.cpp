#include "state_eigen.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "arnoldi.hpp"

namespace feran::detail {

StateEigenpairs sparse_complex_eigen(const ComplexSparseMatrix& M, const ComplexSparseMatrix& D,
                                     const ComplexSparseMatrix& K, Index n_wanted, Real sigma) {
  const Index n = M.rows();
  StateEigenpairs out;
  out.info.method = SolverMethod::shift_invert_arnoldi;
  StateShiftInvert<Complex> op(M, D, K);
  if (!set_shift_or_fail(op, sigma, out.info)) return out;
  op.prepare_inner();
  // Every eigenvalue of the complex problem is a mode of its own (no conjugates to
  // skip): the wanted count and two more, so that real (overdamped, rigid)
  // eigenvalues do not crowd modes out.
  const Index nev = std::min<Index>(2 * n - 1, n_wanted + 2);
  const Index max_size = std::min<Index>(2 * n, std::max<Index>(3 * nev + 1, 20));
  RitzPairs ritz = growing_arnoldi(op, nev, std::min(nev, n_wanted + 1), max_size, arnoldi_tolerance, true);
  out.info.iterations = 1;
  out.info.n_converged = ritz.converged ? ritz.values.size() : 0;
  if (!ritz.converged) {
    out.info.fail(SolverStatus::not_converged, fmt::format("Arnoldi iteration did not converge {} eigenvalues", nev));
    return out;
  }
  out.values = ritz.eigenvalues(sigma);
  out.vectors = std::move(ritz.vectors);
  out.vectors.colwise().normalize();
  return out;
}

}  // namespace feran::detail
