#include "state_eigen.hpp"

#include <algorithm>

#include <Spectra/GenEigsRealShiftSolver.h>
#include <fmt/format.h>

#include "arnoldi.hpp"

namespace feran::detail {

namespace {

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

StateEigenpairs sparse_state_eigen(const SparseMatrix& M, const SparseMatrix& D, const SparseMatrix& K, Index n_wanted,
                                   Real sigma) {
  const Index n = M.rows();
  StateEigenpairs out;
  out.info.method = SolverMethod::shift_invert_arnoldi;
  StateShiftInvert<Real> op(M, D, K);
  const Index nev = n_eigenvalues(n, n_wanted);
  const Index ncv = arnoldi_subspace_size(n, n_wanted);
  if (!set_shift_or_fail(op, sigma, out.info)) return out;
  // First an Arnoldi factorisation grown only as far as the wanted eigenvalues need;
  // when they have not converged within the restarted solver's subspace size,
  // Spectra's implicitly restarted Arnoldi takes over.
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
  RitzPairs ritz = growing_arnoldi(op, nev, nev, ncv, arnoldi_tolerance, false);
  if (ritz.converged) {
    out.info.iterations = 1;
    out.info.n_converged = ritz.values.size();
    values = ritz.eigenvalues(sigma);
    vectors = std::move(ritz.vectors);
  } else {
    Spectra::GenEigsRealShiftSolver<StateShiftInvert<Real>> solver(op, nev, ncv, sigma);
    solver.init();
    const Index n_conv =
        solver.compute(Spectra::SortRule::LargestMagn, 1000, arnoldi_tolerance, Spectra::SortRule::LargestMagn);
    out.info.iterations = solver.num_iterations();
    out.info.n_converged = n_conv;
    if (solver.info() != Spectra::CompInfo::Successful) {
      out.info.fail(SolverStatus::not_converged,
                    fmt::format("Arnoldi iteration converged {} of {} eigenvalues", n_conv, nev));
    }
    values = solver.eigenvalues();
    vectors = solver.eigenvectors().topRows(n);
  }
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
    out.vectors.col(c) = conjugate ? Eigen::VectorXcd(vectors.col(j).conjugate()) : Eigen::VectorXcd(vectors.col(j));
    const Real norm = out.vectors.col(c).norm();
    if (norm > 0) out.vectors.col(c) /= norm;
  }
  return out;
}

}  // namespace feran::detail
