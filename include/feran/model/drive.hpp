#pragma once
/// @file
/// The drive of a torque-driven run-up: a motor's torque against speed and the
/// torques that load it. Theory: docs/theory/time_integration.md (torque-driven
/// run-ups).

#include <utility>
#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// A motor's torque T(Ω) [N m] at rotor speed Ω [rad/s].
struct MotorLaw {
  enum class Kind {
    dc,         ///< T = T_s(1 − Ω/Ω₀): stall torque T_s, no-load speed Ω₀ (a DC shunt motor)
    induction,  ///< Kloss: T = 2T_b/(s/s_b + s_b/s), slip s = (Ω_s − Ω)/Ω_s
    table       ///< (Ω, T) points, linear between them, held beyond the ends
  };
  Kind kind = Kind::dc;
  Real stall_torque = 0.0;                   ///< T_s [N m] (dc)
  Real no_load_speed = 0.0;                  ///< Ω₀ [rad/s] (dc)
  Real synchronous_speed = 0.0;              ///< Ω_s [rad/s] (induction)
  Real breakdown_torque = 0.0;               ///< T_b, the largest torque [N m] (induction)
  Real breakdown_slip = 0.0;                 ///< s_b, the slip of T_b, 0 < s_b < 1 (induction)
  std::vector<std::pair<Real, Real>> table;  ///< (Ω [rad/s], T [N m]), speeds increasing

  Real torque(Real speed) const;
  /// dT/dΩ [N m s/rad].
  Real slope(Real speed) const;
  /// The speed at which the motor alone stops accelerating (T = 0): Ω₀, Ω_s, or the
  /// table's first zero crossing (its last speed when it has none).
  Real free_speed() const;
};

/// The drive: motor, the polar inertia it adds to the rotor's, and the torques that
/// resist the rotation besides the bearings' and the unbalances' reactions.
struct Drive {
  MotorLaw motor;
  Real inertia = 0.0;           ///< polar inertia of the motor's rotor, couplings … [kg m²]
  Real friction_torque = 0.0;   ///< constant resisting torque T_f [N m] (seals, brushes)
  Real viscous_torque = 0.0;    ///< c₁ of a resisting c₁Ω [N m s/rad] (windage, viscous)
  Real quadratic_torque = 0.0;  ///< c₂ of a resisting c₂Ω² [N m s²/rad²] (fan, pump)

  /// The net driving torque without bearings and unbalances: T(Ω) − T_f·σ(Ω) − c₁Ω −
  /// c₂Ω|Ω|, σ(Ω) = Ω/√(Ω² + Ω_ε²) a sign smoothed over Ω_ε = 10⁻³ rad/s (friction
  /// holds no torque at rest).
  Real net_torque(Real speed) const;
  /// d(net_torque)/dΩ.
  Real net_slope(Real speed) const;
};

}  // namespace feran
