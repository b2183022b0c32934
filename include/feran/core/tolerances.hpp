#pragma once
/// @file
/// Tolerances several parts of feran share, named once with their reasons.

#include <feran/core/types.hpp>

namespace feran::tolerance {

/// Two eigenvalues closer than this, relative to their magnitude, are one repeated
/// eigenvalue (kept together, split by whirl): far above the round-off of the QR and
/// Arnoldi solvers (~1e-13 relative), far below any physical split of a rotor's modes.
inline constexpr Real repeated_eigenvalue = 1e-7;

/// A matrix counts as symmetric, Hermitian or skew when A ∓ Aᵀ (or Aᴴ) is at most this
/// times its largest entry: the round-off of assembling a sum of element matrices.
inline constexpr Real symmetry = 1e-12;

/// A motion is rigid (no strain energy) when its Rayleigh quotient xᵀKx/xᵀMx is below
/// this times the largest K_ii/M_ii: a natural frequency 10⁻⁶ times the highest one,
/// far above round-off (~1e-16 times the largest).
inline constexpr Real rigid_body = 1e-12;
/// The same for a model whose vibrations reach below rigid_body (a fine mesh: the
/// highest natural frequency grows with the number of elements, so the lowest can be
/// 10⁻⁶ of it and less): a frequency 10⁻⁷ times the highest, still 100 times the
/// round-off. Used only where the spectrum has eigenvalues between the two.
inline constexpr Real rigid_body_floor = 1e-14;

/// A computed eigenvalue is real when |Im p| is at most this times |p|: the round-off
/// of the complex arithmetic of the solvers.
inline constexpr Real real_eigenvalue = 1e-10;

/// A mode whose directivity (forward minus backward kinetic share, in [−1, 1]) is at
/// most this in magnitude does not whirl either way (a straight-line orbit, e.g. an
/// anisotropic rotor at rest): round-off of the mode shape is ~1e-13, while the
/// weakest gyroscopic coupling of a spinning rotor on anisotropic bearings gives
/// 1e-3 and more.
inline constexpr Real planar_directivity = 1e-6;

}  // namespace feran::tolerance
