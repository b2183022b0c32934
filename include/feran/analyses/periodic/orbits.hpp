#pragma once
/// @file
/// Branches of steady states of a condensed rotor over speed: its static equilibrium
/// with the eigenvalues there (Hopf points where a pair crosses into the right
/// half-plane), forced orbits at the rotor speed (unbalance), and self-excited orbits
/// (oil whirl and whip, friction whirl) leaving a Hopf point, each orbit with its
/// Floquet multipliers, and the bifurcations along each branch located on it.
/// Theory: docs/theory/harmonic_balance.md.

#include <functional>
#include <list>
#include <memory>
#include <string>
#include <vector>

#include <feran/analyses/periodic/condensed_rotor.hpp>
#include <feran/analyses/periodic/continuation.hpp>
#include <feran/analyses/periodic/floquet.hpp>
#include <feran/core/types.hpp>

namespace feran {

struct SteadyState;

struct OrbitSettings {
  FourierBasis fourier{.harmonics = 8, .samples = 64};
  ContinuationSettings continuation;  ///< p_min, p_max: the speed range [rad/s]
  /// The length [m] the orbit's coefficients are scaled by in the continuation (0: the
  /// smallest clearance of the supports, else 1 mm).
  Real length_scale = 0.0;
  /// An orbit is unstable when a multiplier's modulus exceeds 1 + this (an
  /// equilibrium: when an eigenvalue's real part exceeds this times its modulus).
  Real stability_tolerance = 1e-7;
  /// Called with each new state of a branch; returning false ends the branch there
  /// (ended_by "stopped"): a door's stop request and progress.
  std::function<bool(const SteadyState&)> monitor = {};
};

/// What a branch is continued in: the rotor and its speed at each value p of the
/// parameter — the speed itself, or a number of the model (a bearing's clearance, the
/// oil's viscosity, an unbalance, a stiffness: any parameter path) at a fixed speed.
class RotorFamily {
 public:
  /// The speed as the parameter: the one rotor at every p, Ω = p.
  explicit RotorFamily(const CondensedRotor& rotor);
  /// A number of the model as the parameter at the fixed speed @p speed [rad/s]:
  /// @p build makes the model with the parameter at p, and each is condensed on the
  /// basis of @p rotor (the model at the branch's start), so that the coefficients keep
  /// their meaning. @p name names the parameter (its path) in messages. @p rotor must
  /// outlive the family.
  RotorFamily(const CondensedRotor& rotor, Real speed, std::function<Model(Real)> build, std::string name);

  /// The rotor at parameter @p p (the last few built are kept).
  const CondensedRotor& at(Real p) const;
  /// The speed at parameter @p p [rad/s].
  Real speed(Real p) const { return build_ ? speed_ : p; }
  bool is_speed() const { return !build_; }
  /// The rotor the family starts from (its coordinates are every member's).
  const CondensedRotor& base() const { return base_; }
  /// "speed", or the parameter's name.
  const std::string& name() const { return name_; }

 private:
  struct Member {
    Real p;
    std::unique_ptr<Model> model;
    std::unique_ptr<CondensedRotor> rotor;
  };
  const CondensedRotor& base_;
  Real speed_ = 0.0;
  std::function<Model(Real)> build_;
  std::string name_ = "speed";
  mutable std::list<Member> cache_;
};

/// The length [m] a branch's coefficients are scaled by: OrbitSettings::length_scale,
/// or the smallest clearance of the family's supports, else 1 mm.
Real length_scale(const RotorFamily& family, const OrbitSettings& settings);

/// One steady state.
struct SteadyState {
  Real parameter = 0.0;  ///< the branch's parameter p (the speed [rad/s], or the number a path names, SI)
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
  SteadyState at;     ///< the state there
  std::size_t after;  ///< between orbits `after` and `after` + 1 of the branch
};

/// The name of a kind ("fold", "period_doubling", "neimark_sacker", "hopf", "static_instability").
const char* bifurcation_name(Bifurcation::Kind kind);

/// The frequency [rad/s] of the motion a bifurcation lets grow: at a Hopf point the
/// whirl's (the imaginary part of the critical eigenvalue), at a Neimark–Sacker point
/// the new one, arg μ/2π of the orbit's (the critical multiplier's angle; the motion
/// then holds it and its difference with the orbit's harmonics), at a period doubling
/// half the orbit's; 0 at a fold or a static instability.
Real critical_frequency(const Bifurcation& b);

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

/// The name of a branch kind ("equilibrium", "forced", "self_excited").
const char* branch_kind_name(OrbitBranch::Kind kind);

/// The static equilibrium over [p_min, p_max] from p_min (continuation of the balance
/// with harmonic 0 alone), its eigenvalues at each point, and Hopf points. The
/// CondensedRotor forms continue in speed.
OrbitBranch equilibrium_branch(const RotorFamily& family, const OrbitSettings& settings);
OrbitBranch equilibrium_branch(const CondensedRotor& rotor, const OrbitSettings& settings);

/// The orbits forced by the unbalance (ω = Ω) over [p_min, p_max] from p_min, or from
/// p_max towards p_min when @p downwards (a run-down). Folds, period doubling and
/// Neimark–Sacker points are located on it.
OrbitBranch forced_branch(const RotorFamily& family, const OrbitSettings& settings, bool downwards = false);
OrbitBranch forced_branch(const CondensedRotor& rotor, const OrbitSettings& settings, bool downwards = false);

/// The self-excited orbits leaving the Hopf point @p hopf of an equilibrium branch,
/// their base frequency an unknown fixed in phase by the first harmonic's sine of the
/// largest component of the critical mode; continued within [p_min, p_max].
OrbitBranch hopf_branch(const RotorFamily& family, const Bifurcation& hopf, const OrbitSettings& settings);
OrbitBranch hopf_branch(const CondensedRotor& rotor, const Bifurcation& hopf, const OrbitSettings& settings);

/// The branch through a given orbit @p start — one of another branch (in another
/// parameter, or with other harmonics), or one found otherwise — continued from it
/// towards increasing parameter (decreasing with @p downwards) within
/// [p_min, p_max]: a forced orbit (@p kind forced, ω = Ω) or a self-excited one
/// (@p kind self_excited, ω from @p start.frequency an unknown). The start is its
/// coefficients @p start.X on the condensed coordinates of @p family's rotor (padded with
/// zeros or cut to the harmonics of @p settings.fourier) at @p start.parameter, the
/// family's parameter; a self-excited start is first shifted in phase so that the
/// first harmonic's sine of its largest first-harmonic coordinate is 0 (its phase
/// condition). The start is corrected at its parameter first, so it need only be near
/// an orbit. Throws Error when it does not converge there.
OrbitBranch branch_through(const RotorFamily& family, const SteadyState& start, OrbitBranch::Kind kind,
                           const OrbitSettings& settings, bool downwards = false);

/// The states of @p branch at parameter @p p (the speed): one wherever the branch crosses it
/// (several where it folds back), each solved at that speed from the interpolation
/// between the branch's points on either side. Empty when the branch does not reach
/// the speed.
std::vector<SteadyState> states_at(const RotorFamily& family, const OrbitBranch& branch, Real p,
                                   const OrbitSettings& settings);
std::vector<SteadyState> states_at(const CondensedRotor& rotor, const OrbitBranch& branch, Real speed,
                                   const OrbitSettings& settings);

/// The displacements @p x and velocities @p v of all unconstrained DOFs on the orbit
/// at phase θ = ωt (an equilibrium: its displacements, no velocity).
void orbit_state(const CondensedRotor& rotor, const SteadyState& orbit, const FourierBasis& fourier, Real theta,
                 Vector& x, Vector& v);

}  // namespace feran
