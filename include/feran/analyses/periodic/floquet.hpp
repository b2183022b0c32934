#pragma once
/// @file
/// Stability of a periodic orbit: its Floquet exponents s (the perturbation grows as
/// e^{st}·p(t), p periodic) and multipliers μ = e^{sT}, T = 2π/ω, by Hill's method from
/// the harmonic-balance Jacobian, or from the monodromy matrix of one period integrated
/// in time. Theory: docs/theory/harmonic_balance.md ("Stability").

#include <feran/analyses/periodic/harmonic_balance.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// The exponents and multipliers of an orbit, 2n of each for n DOFs.
struct Floquet {
  ComplexVector exponents;    ///< s, each with Im s in [−ω/2, ω/2] as far as the method tells
  ComplexVector multipliers;  ///< μ = e^{sT}
  /// The largest |μ| (without the one multiplier 1 an autonomous orbit has by its
  /// free phase, when told so).
  Real largest = 0.0;
  /// Index of the multiplier set aside as the phase's (autonomous orbits), or −1.
  Index trivial = -1;
};

/// Hill's method: with P the perturbation's coefficients on the same harmonics as the
/// orbit, (s²·M̃ + s·C̃ + K̃)P = 0, where K̃ = ∂R/∂X (the balance's Jacobian),
/// M̃ = I ⊗ M and C̃ = I ⊗ C + 2ω(∇ ⊗ M) − ∂F/∂V. Its 2n(2H + 1) eigenvalues are the
/// 2n exponents repeated at s + ikω (and, towards the truncation, poorer copies):
/// the 2n kept are those whose eigenvectors are centred on harmonic 0 — the weighted
/// mean k̄ of their complex-exponential harmonics −H … H nearest 0 (Lazarus & Thomas
/// 2010; Guillot et al. 2020) — among those the harmonics resolve (Re s ≥ −Hω/2);
/// strongly damped exponents, whose copies the truncated matrix mixes, fill the rest
/// (their multipliers, of modulus below e^{−πH}, do not decide stability).
/// @p terms: balance_terms(…, true) at the orbit.
/// With @p autonomous the multiplier nearest 1 is the phase's and is set aside.
Floquet hill_floquet(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const BalanceTerms& terms,
                     bool autonomous);

/// How monodromy_floquet() integrates the linearised equations over one period.
enum class MonodromyScheme {
  /// The classical Runge–Kutta method (error O(steps⁻⁴)); explicit, so the steps must
  /// resolve the stiffest motion (a bearing film's): the independent check.
  runge_kutta,
  /// The fourth-order commutator-free exponential integrator of Blanes & Moan (2006)
  /// and Thalhammer (2006): per step, two exponentials of the state matrix at the
  /// step's two Gauss points combined. Stable at any step for the stiff film
  /// motions; on strongly nonlinear orbits its order drops towards three (stiff
  /// order reduction).
  exponential,
};

/// The multipliers from the monodromy matrix: the linearised equations
/// M δẍ + (C − ∂f/∂ẋ(t)) δẋ + (K − ∂f/∂x(t)) δx = 0 along the orbit @p X integrated over
/// one period in @p steps steps by @p scheme, and Φ(T)'s eigenvalues; s = ln μ / T with
/// Im s in (−ω/2, ω/2]. With @p autonomous the phase's multiplier, whose eigenvector
/// is the orbit's own velocity ż(0) = (ẋ, ẍ) at t = 0, is projected out: the other
/// 2n − 1 are the eigenvalues of QᵀΦQ, Q an orthonormal basis of ż(0)'s complement,
/// and the phase's is reported as exactly 1 (Floquet::trivial, the last).
Floquet monodromy_floquet(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X,
                          Index steps, bool autonomous, MonodromyScheme scheme = MonodromyScheme::runge_kutta);

}  // namespace feran
