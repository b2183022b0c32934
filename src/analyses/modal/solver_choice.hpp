#pragma once
// The automatic choice between the dense solvers and shift-invert Arnoldi for one
// decoupled block: a cost model of each, in seconds on the machine the constants
// were measured on (only their ratio decides). docs/theory/modal_analysis.md,
// "Choosing the solver", gives the model and how it was fitted.

#include <feran/core/types.hpp>

namespace feran::detail {

/// What decides the work of either solver besides the block's size.
struct BlockForm {
  /// Solved in complex forward/backward coordinates (an axisymmetric block): half
  /// the order in complex arithmetic.
  bool complex = false;
  /// Undamped and conservative (no damping, no circulatory stiffness): the dense
  /// solver takes the Hermitian-definite form.
  bool hermitian = false;
};

/// Estimated time of the dense solve of a block of @p n DOF.
Real dense_cost(Index n, BlockForm form);

/// Estimated time of shift-invert Arnoldi for @p n_wanted modes of a block of
/// @p n DOF: one sparse LU, the Krylov basis to its first convergence check, and the
/// Ritz values of the projected matrix.
Real arnoldi_cost(Index n, Index n_wanted, BlockForm form);

/// Whether Arnoldi is expected to be cheaper than the dense solve.
inline bool arnoldi_cheaper(Index n, Index n_wanted, BlockForm form) {
  return arnoldi_cost(n, n_wanted, form) < dense_cost(n, form);
}

}  // namespace feran::detail
