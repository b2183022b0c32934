#pragma once
/// @file
/// Harmonic balance of a small dense second-order system with nonlinear forces: the
/// periodic orbit of base frequency ω as the root of the balance of its Fourier
/// coefficients, by Newton's method with the exact Jacobian of the AFT step
/// (aft.hpp). The rotor's analysis condenses its model onto the nonlinear DOFs and
/// solves this. Theory: docs/theory/harmonic_balance.md.

#include <vector>

#include <feran/analyses/periodic/aft.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// M x'' + C x' + K x = f_e(t) + f(t, x, x') on n DOFs, f_e given by its Fourier
/// coefficients, f by a LocalForce on all n DOFs (empty: linear).
struct PeriodicSystem {
  Matrix M, C, K;    ///< n × n
  Vector external;   ///< f_e's n(2H + 1) coefficients (empty: none)
  LocalForce force;  ///< the nonlinear force (may be empty)
  /// The DOFs the force acts on, in the order of its local x (empty: all n). The AFT
  /// then works on these alone, and its cost does not grow with the other DOFs.
  std::vector<Index> force_dofs = {};
};

/// The balance's residual and its derivatives at (ω, X).
struct BalanceTerms {
  Vector R;          ///< L(ω)X − F_e − F(X)
  Matrix dR_dX;      ///< L(ω) − ∂F/∂X
  Vector dR_domega;  ///< (∂L/∂ω)X − ∂F/∂ω, F_e held fixed
  Matrix Jv;         ///< ∂F/∂V (velocity coefficients), n(2H + 1) square; when asked for
  Real scale = 0.0;  ///< the largest of ‖L·X‖, ‖F_e‖ and ‖F(X)‖
};

/// R and its derivatives. With @p velocity_jacobian, Jv as well (Hill's method).
BalanceTerms balance_terms(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X,
                           bool velocity_jacobian = false);

/// R alone (no Jacobians): L(ω)X − F_e − F(X).
Vector balance_residual(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X);

/// The force's harmonics H + 1 … 3H along the orbit @p X relative to its harmonics
/// 0 … H (BalanceResult::truncation).
Real truncation_estimate(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X);

/// Newton's method on the balance.
struct BalanceSettings {
  Real tolerance = 1e-10;  ///< on ‖R‖ relative to the largest of ‖L·X‖, ‖f_e‖ and ‖F(X)‖
  int max_iterations = 50;
};

/// A solved (or not) balance.
struct BalanceResult {
  Vector X;  ///< the orbit's coefficients (the last iterate if not converged)
  bool converged = false;
  int iterations = 0;
  Real residual = 0.0;  ///< the relative residual reached
  /// The truncation estimate: the nonlinear force's harmonics H + 1 … 3H along the
  /// orbit, which the balance leaves out, relative to its harmonics 0 … H (‖·‖ of their
  /// coefficients). Small when H harmonics represent the orbit; add harmonics when it
  /// is not. 0 without a nonlinear force.
  Real truncation = 0.0;
  Matrix jacobian;  ///< ∂R/∂X at X (Floquet analysis and continuation start from it)
};

/// The coefficients of L(ω)·X: the linear part's balance, harmonic by harmonic
/// (K c₀; for harmonic k, (K − k²ω²M)a_k + kωC b_k and (K − k²ω²M)b_k − kωC a_k).
Matrix linear_balance(const FourierBasis& basis, const PeriodicSystem& system, Real omega);

/// The periodic orbit of base frequency @p omega from the start @p X0 (n(2H + 1)
/// values): R(X) = L(ω)X − f_e − F(X) = 0. A step that does not lower ‖R‖ is halved
/// (up to 20 times); the result says whether it converged and keeps the last iterate.
BalanceResult solve_balance(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X0,
                            const BalanceSettings& settings = {});

}  // namespace feran
