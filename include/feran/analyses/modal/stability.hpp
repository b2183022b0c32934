#pragma once
/// @file
/// Whether the rotor's free motion about its equilibrium grows at a speed: the
/// stability of M q'' + (C + C_i + Ω G) q' + (K + Ω K_i) q = 0 with the supports
/// linearised (analyses/static/equilibrium.hpp). Steady-state results carry it at each
/// point, so that a response is never reported without saying that the rotor cannot
/// run there (docs/theory/stability.md).
///
/// Decided in one of two ways:
///  - without eigenvalues when every element's stiffness and damping are symmetric and
///    positive semidefinite and nothing is circulatory (no Ω·K_i, no cross-coupled
///    bearing, no frequency-dependent coefficient): then the energy
///    ½(q'ᵀMq' + qᵀKq) never grows (the gyroscopic forces do no work), and the motion
///    is stable (Lyapunov; Meirovitch, "Methods of Analytical Dynamics", 1970, §6.7);
///  - otherwise from the modal analysis at that speed (all modes up to its dense
///    limit, else its 12 lowest): unstable when an eigenvalue that is not a rigid-body
///    mode has a positive real part — an oscillating mode with negative damping
///    (flutter: oil whirl, internal damping) or a real positive eigenvalue
///    (divergence: a negative stiffness, a shaft loaded beyond buckling).

#include <string>

#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

struct StabilityPoint {
  Real speed = 0;  ///< [rad/s]
  /// The stability was decided (the energy test passed, or the modal analysis
  /// converged); false: unknown, with the reason in message.
  bool known = true;
  bool unstable = false;
  /// Decided by the energy test: stable, no eigenvalue computed (growth_rate NaN).
  bool by_energy = false;
  /// Largest real part of a non-rigid eigenvalue [1/s] (> 0: unstable); NaN when not
  /// computed.
  Real growth_rate = 0;
  /// That mode's damped frequency [Hz]; 0 for a real eigenvalue.
  Real frequency_hz = 0;
  /// The growing mode is a real eigenvalue: divergence, not flutter.
  bool divergence = false;
  std::string message;  ///< why unknown

  /// Stability unknown at @p at_speed, for the reason @p why.
  static StabilityPoint unknown(Real at_speed, std::string why);
};

/// The stability of @p model at @p speed [rad/s]. An oil film needs speed > 0: at rest
/// the result is unknown with the reason.
StabilityPoint stability_at(const Model& model, Real speed);

/// The same for a model whose supports are already linearised (linearised(): no force
/// carries the rotor), about whichever equilibrium they were linearised.
StabilityPoint stability_of_linear(const Model& linear, Real speed);

/// One phrase for @p point: "stable", "UNSTABLE: flutter, a mode at 41.2 Hz grows at
/// 3.05 1/s", "UNSTABLE: divergence, a real eigenvalue 70.7 1/s", "unknown: <reason>".
std::string stability_phrase(const StabilityPoint& point);

/// "stable", "flutter", "divergence" or "unknown" (machine-readable).
std::string stability_kind(const StabilityPoint& point);

/// True when the energy test alone shows @p model stable at @p speed (see above); the
/// supports must already be linearised.
bool energy_stable(const Model& linear, Real speed);

}  // namespace feran
