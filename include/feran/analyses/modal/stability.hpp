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

#include <memory>
#include <mutex>
#include <string>
#include <vector>

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

class ModalSolver;  // feran/analyses/modal/modal.hpp

/// stability_of_linear() at many speeds of one model, for the analyses that judge every
/// point of a sweep: what does not depend on speed is done once — the energy test of
/// the elements whose matrices do not change with speed or frequency (their K_i
/// decides at every speed above 0), and the modal solver, made on first need and
/// reused (its assembly, and the blocks of modes that no speed changes). at() gives
/// what stability_of_linear() gives at that speed, and may be called from several
/// threads.
class StabilityScan {
 public:
  /// @p linear: the model with its supports linearised (or without supports); it must
  /// outlive the scan. @p needs_speed: the model's supports are oil films
  /// (needs_speed() of the model before linearising): at rest the stability is unknown.
  explicit StabilityScan(const Model& linear, bool needs_speed = false);
  StabilityPoint at(Real speed) const;

 private:
  bool energy_stable_at(Real speed) const;
  const ModalSolver& solver() const;

  const Model& linear_;
  bool needs_speed_ = false;
  bool constant_stable_ = true;        // the constant elements pass the energy test
  bool constant_circulatory_ = false;  // some constant element has a non-zero K_i
  std::vector<std::size_t> varying_;   // the elements that depend on speed or frequency
  mutable std::once_flag solver_once_;
  mutable std::shared_ptr<const ModalSolver> solver_;
};

}  // namespace feran
