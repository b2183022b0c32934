#pragma once
/// @file
/// The alternating frequency–time (AFT) step of harmonic balance: the Fourier
/// coefficients of a nonlinear force along a periodic motion given by its Fourier
/// coefficients, and their exact Jacobian with respect to those coefficients, from the
/// force's own Jacobians ∂f/∂x and ∂f/∂v at the time samples (Cameron & Griffin,
/// J. Appl. Mech. 56, 1989). Theory: docs/theory/harmonic_balance.md.
///
/// A motion of n DOFs with H harmonics of the base frequency ω is
///   x(t) = c₀ + Σ_{k=1..H} (a_k cos kωt + b_k sin kωt),
/// stored harmonic by harmonic, n values each: [c₀, a₁, b₁, …, a_H, b_H], n(2H + 1)
/// values. Forces follow the same layout.

#include <functional>

#include <feran/core/types.hpp>
#include <feran/model/force.hpp>

namespace feran {

/// The harmonics kept and the time samples of one period.
struct FourierBasis {
  Index harmonics = 1;  ///< H: harmonics 0 … H of the base frequency
  Index samples = 8;    ///< N time samples per period; at least 2H + 1

  /// Values per DOF, 2H + 1.
  Index terms() const { return 2 * harmonics + 1; }
  /// Throws Error unless H ≥ 0 and N ≥ 2H + 1.
  void check() const;
};

/// A nonlinear force on n local DOFs at time @p t of the period, with the local motion
/// x, v: its value and Jacobian blocks (as Force::force gives them).
using LocalForce = std::function<NonlinearForceValue(Real t, const Vector& x, const Vector& v)>;

/// The Fourier coefficients of a force along a motion, and their Jacobian.
struct AftResult {
  Vector F;  ///< n(2H + 1) force coefficients
  Matrix J;  ///< ∂F/∂X, n(2H + 1) square
  /// ∂F/∂ω at fixed X: the force's change through the velocities ẋ = ω·(γ'(θ) ⊗ I)X
  /// (a force's explicit dependence on time is taken to follow the phase θ = ωt).
  Vector dF_domega;
  /// ∂F/∂V, the Jacobian with respect to the velocity's own coefficients V (the
  /// transform of ∂f/∂ẋ; J = ∂F/∂X_x + Jv·ω∇): Hill's method needs it apart. Empty
  /// unless asked for.
  Matrix Jv;
};

/// The motion's coefficients @p X (n(2H + 1) values, n = X.size()/(2H + 1)) sampled at
/// the N times t_j = 2πj/(Nω) of one period; the force evaluated there; its
/// coefficients by the discrete Fourier transform, exact for force harmonics up to
/// N − H − 1 (no aliasing into the kept ones); the Jacobian likewise from ∂f/∂x and
/// ∂f/∂v. Throws Error for a coefficient vector of the wrong length.
/// With @p velocity_jacobian, Jv is filled as well.
AftResult aft(const FourierBasis& basis, Real omega, const Vector& X, const LocalForce& force,
              bool velocity_jacobian = false);

/// The force's coefficients F alone (no Jacobian): N force evaluations and the DFT.
Vector force_coefficients(const FourierBasis& basis, Real omega, const Vector& X, const LocalForce& force);

/// The coefficients of dx/dθ for a motion with coefficients @p X: ∇X, harmonic k's
/// (a_k, b_k) becoming (k·b_k, −k·a_k), the mean 0.
Vector phase_derivative(const FourierBasis& basis, const Vector& X);

/// The motion at time @p t: x(t) and v(t) from its coefficients.
void motion_at(const FourierBasis& basis, Real omega, const Vector& X, Real t, Vector& x, Vector& v);

}  // namespace feran
