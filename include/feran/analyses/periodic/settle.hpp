#pragma once
/// @file
/// A run of the condensed rotor at constant speed until its motion repeats, and the
/// periodic orbit it settled on: a start for branch_through that no continuation from
/// the equilibrium reaches — an orbit beyond a fold, a branch detached from the others,
/// a whirl where the equilibrium is unstable over the whole range of a parameter, the
/// orbit a machine was seen to run on. Theory: docs/theory/harmonic_balance.md ("A
/// branch through a settled orbit").

#include <functional>

#include <feran/analyses/periodic/orbits.hpp>
#include <feran/core/types.hpp>

namespace feran {

struct SettleSettings {
  /// The longest simulated time [s]; 0: 2000 revolutions of the rotor.
  Real duration = 0.0;
  /// Time steps per revolution of the rotor (BDF2, second order and L-stable: the
  /// film's stiff modes are damped, not carried along).
  Index steps = 64;
  /// The motion has settled when its extent and its mean over a window of
  /// `window` revolutions differ from the previous window's by less than this,
  /// relative to the extent.
  Real tolerance = 1e-3;
  Index window = 20;
  /// Called with the simulated time now and at the end; returning false stops the run
  /// (it then throws Error "stopped").
  std::function<bool(Real time, Real end)> watch = {};
};

/// The orbit a run settled on, on the harmonics of the orbit settings.
struct SettledOrbit {
  SteadyState start;  ///< parameter, speed, frequency (ω), X; not yet corrected by the balance
  OrbitBranch::Kind kind = OrbitBranch::Kind::forced;  ///< forced (ω = Ω) or self_excited
  Real time = 0.0;                                     ///< the simulated time until the motion had settled [s]
  Real mismatch = 0.0;  ///< ‖x(t + T) − x(t)‖ over the last period, relative to the motion's extent
};

/// Runs the rotor of @p family at parameter @p p (its speed family.speed(p) > 0, held
/// constant) from its static equilibrium (from the centre when that is not found) with
/// the coordinates of its nonlinear forces displaced by a hundredth of the length
/// scale, by BDF2 on the condensed coordinates, until its motion settles; then one
/// more period, whose Fourier coefficients (by the discrete transform of its samples)
/// are the orbit. The orbit is forced when the rotor is (loads at the rotor speed: ω =
/// Ω, the phase that of the rotor's angle), else self-excited, ω from the mean
/// crossings of its largest coordinate over the last window.
/// Throws Error with the reason when there is no periodic orbit to take: the motion
/// dies out onto the equilibrium (self-excited only), grows beyond a hundred length
/// scales, has not settled within the duration, or does not repeat after one period
/// (by more than 1 %: quasi-periodic, or a period doubled).
SettledOrbit settle_orbit(const RotorFamily& family, Real p, const OrbitSettings& settings,
                          const SettleSettings& run = {});

}  // namespace feran
