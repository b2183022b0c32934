#pragma once
/// @file
/// How a solve went: its method and status (the idea of Spectra's CompInfo and
/// Eigen's info()). Numerical trouble is recorded here, never thrown.

#include <string>
#include <string_view>

#include <feran/core/types.hpp>

namespace feran {

/// The numerical method of a solve.
enum class SolverMethod {
  none,                  ///< nothing was solved yet
  dense_hermitian,       ///< undamped gyroscopic blocks: Hermitian-definite pencil (zheevd)
  dense_qr,              ///< all modes: Hessenberg-QR of the state matrix (LAPACK)
  shift_invert_lanczos,  ///< undamped blocks without gyroscopic terms: symmetric Lanczos
  shift_invert_arnoldi,  ///< the lowest modes: shift-invert Arnoldi
  sparse_lu,             ///< a linear system: sparse LU
  banded_lu,             ///< a linear system of small bandwidth: banded LU with partial pivoting (LAPACK)
  time_integration,      ///< a time integrator (TransientResult names which)
  harmonic_balance,      ///< periodic orbits: harmonic balance continued along a branch
};

/// How a solve ended.
enum class SolverStatus {
  success,            ///< every value asked for was computed
  not_converged,      ///< an iteration did not converge (results so far kept)
  numerical_failure,  ///< a singular matrix, a non-finite value or a blow-up (results so far kept)
  interrupted,        ///< stopped on request (StopToken) at a clean point (results so far kept)
};

/// The name results and reports use: "dense-qr", "shift-invert-arnoldi", "sparse-lu", …
std::string_view to_string(SolverMethod method);
/// "success", "not-converged", "numerical-failure", "interrupted".
std::string_view to_string(SolverStatus status);

/// Convergence record of a solve (never an exception: callers decide).
struct SolverInfo {
  SolverMethod method = SolverMethod::none;
  SolverStatus status = SolverStatus::success;
  Index n_converged = 0;  ///< eigenvalues converged (sparse) or computed (dense)
  Index iterations = 0;   ///< restarts of the Arnoldi iteration (sparse)
  std::string message;    ///< why it did not succeed, when it did not

  bool converged() const { return status == SolverStatus::success; }
  /// Records a failure with its reason.
  void fail(SolverStatus why, std::string reason) {
    status = why;
    message = std::move(reason);
  }
};

}  // namespace feran
