#pragma once
/// @file
/// Branches of steady states of a condensed rotor over speed: its static equilibrium
/// with the eigenvalues there (Hopf points where a pair crosses into the right
/// half-plane), forced orbits at the rotor speed (unbalance), and self-excited orbits
/// (oil whirl and whip, friction whirl) leaving a Hopf point, each orbit with its
/// Floquet multipliers, and the bifurcations along each branch located on it.
/// Theory: docs/theory/harmonic_balance.md.

#include <optional>
#include <string>
#include <vector>

#include <feran/analyses/periodic/condensed_rotor.hpp>
#include <feran/analyses/periodic/continuation.hpp>
#include <feran/analyses/periodic/floquet.hpp>
#include <feran/core/types.hpp>

namespace feran {

struct OrbitSettings {
  FourierBasis fourier{.harmonics = 8, .samples = 64};
  ContinuationSettings continuation;  ///< p_min, p_max: the speed range [rad/s]
  /// The length [m] the orbit's coefficients are scaled by in the continuation (0: the
  /// smallest clearance of the supports, else 1 mm).
  Real length_scale = 0.0;
  /// An orbit is unstable when a multiplier's modulus exceeds 1 + this (an
  /// equilibrium: when an eigenvalue's real part exceeds this times its modulus).
  Real stability_tolerance = 1e-7;
};

/// One steady state.
struct SteadyState {
  Real speed = 0.0;      ///< Ω [rad/s]
  Real frequency = 0.0;  ///< base frequency ω [rad/s] (an equilibrium: 0)
  Vector X;              ///< coefficients of the condensed coordinates
  /// Floquet exponents and multipliers (an equilibrium: its eigenvalues as exponents,
  /// and e^{s·2π/Ω} as multipliers).
  Floquet floquet;
  bool stable = true;
  Real truncation = 0.0;  ///< BalanceResult::truncation
  Real residual = 0.0;
};

/// A bifurcation located on a branch.
struct Bifurcation {
  enum class Kind { fold, period_doubling, neimark_sacker, hopf, static_instability };
  Kind kind = Kind::fold;
  SteadyState at;           ///< the state there
  std::size_t after;  ///< between orbits `after` and `after` + 1 of the branch
};

/// The name of a kind ("fold", "period_doubling", "neimark_sacker", "hopf", "static_instability").
const char* bifurcation_name(Bifurcation::Kind kind);

struct OrbitBranch {
  enum class Kind { equilibrium, forced, self_excited };
  Kind kind = Kind::equilibrium;
  std::vector<SteadyState> orbits;
  std::vector<Bifurcation> bifurcations;
  std::string ended_by;  ///< Branch::ended_by
  bool clipped = false;  ///< it ended on the speed range's limit
  /// A self-excited branch from a Hopf point: "supercritical" (it leaves towards the
  /// speeds where the equilibrium is unstable, its orbits stable there) or
  /// "subcritical" (it leaves towards the stable side, unstable orbits that bound the
  /// equilibrium's region of attraction); empty otherwise.
  std::string criticality;
  /// The harmonic balance's harmonics and samples the branch was computed with.
  FourierBasis fourier;
  /// A self-excited branch: the coefficient held at 0 to fix the phase (−1: none).
  Index phase_anchor = -1;
};

/// The static equilibrium over [p_min, p_max] from p_min (continuation in speed of the
/// balance with harmonic 0 alone), its eigenvalues at each speed, and Hopf points.
OrbitBranch equilibrium_branch(const CondensedRotor& rotor, const OrbitSettings& settings);

/// The orbits forced by the unbalance (ω = Ω) over [p_min, p_max] from p_min, or from
/// p_max towards p_min when @p downwards (a run-down). Folds, period doubling and
/// Neimark–Sacker points are located on it.
OrbitBranch forced_branch(const CondensedRotor& rotor, const OrbitSettings& settings, bool downwards = false);

/// The self-excited orbits leaving the Hopf point @p hopf of an equilibrium branch,
/// their base frequency an unknown fixed in phase by the first harmonic's sine of the
/// largest component of the critical mode; continued in speed within [p_min, p_max].
OrbitBranch hopf_branch(const CondensedRotor& rotor, const Bifurcation& hopf, const OrbitSettings& settings);

/// The states of @p branch at speed @p speed: one wherever the branch crosses it
/// (several where it folds back), each solved at that speed from the interpolation
/// between the branch's points on either side. Empty when the branch does not reach
/// the speed.
std::vector<SteadyState> states_at(const CondensedRotor& rotor, const OrbitBranch& branch, Real speed,
                                   const OrbitSettings& settings);

/// The displacements @p x and velocities @p v of all unconstrained DOFs on the orbit
/// at phase θ = ωt (an equilibrium: its displacements, no velocity).
void orbit_state(const CondensedRotor& rotor, const SteadyState& orbit, const FourierBasis& fourier, Real theta,
                 Vector& x, Vector& v);

}  // namespace feran
