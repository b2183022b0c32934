#pragma once
/// @file
/// A basis of undamped modes for reduced (projected) time integration.

#include <vector>

#include <feran/assembly/assembler.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// The largest model, in reduced DOFs, for which undamped_mode_basis() solves its
/// dense eigenproblems.
inline constexpr Index modal_basis_max_dofs = 1500;

/// The @p modes lowest undamped modes of (K_s(Ω), M) at each speed of @p speeds
/// [rad/s], K_s the symmetric stiffness with the speed-dependent coefficients at Ω
/// (K_i and the damping left out), together with the static responses K_s⁻¹·f to
/// the columns f of @p loads (reduced coordinates; the static correction that makes
/// up for the truncated modes' flexibility where forces act), merged into one
/// M-orthonormal basis (Φᵀ·M·Φ = I). Directions that the vectors share are kept once
/// (Gram eigenvalues below 1e-10 of the largest are dropped). Sampling several speeds
/// lets the basis follow speed-dependent bearings (a stiffness step, the arctan
/// law). Throws feran::Error when @p modes is not in [1, n] or the model has more
/// than modal_basis_max_dofs.
Matrix undamped_mode_basis(const Assembler& assembler, const std::vector<Real>& speeds, Index modes,
                           const Matrix& loads = Matrix());

}  // namespace feran
