#include <feran/analyses/common/solver_info.hpp>

namespace feran {

std::string_view to_string(SolverMethod method) {
  switch (method) {
    case SolverMethod::none:
      return "none";
    case SolverMethod::dense_hermitian:
      return "dense-hermitian";
    case SolverMethod::dense_qr:
      return "dense-qr";
    case SolverMethod::shift_invert_lanczos:
      return "shift-invert-lanczos";
    case SolverMethod::shift_invert_arnoldi:
      return "shift-invert-arnoldi";
    case SolverMethod::sparse_lu:
      return "sparse-lu";
    case SolverMethod::banded_lu:
      return "banded-lu";
    case SolverMethod::time_integration:
      return "time-integration";
    case SolverMethod::harmonic_balance:
      return "harmonic-balance";
  }
  return "none";
}

std::string_view to_string(SolverStatus status) {
  switch (status) {
    case SolverStatus::success:
      return "success";
    case SolverStatus::not_converged:
      return "not-converged";
    case SolverStatus::numerical_failure:
      return "numerical-failure";
    case SolverStatus::interrupted:
      return "interrupted";
  }
  return "success";
}

}  // namespace feran
