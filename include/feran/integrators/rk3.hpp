#pragma once
/// @file
/// Explicit third-order Runge–Kutta method ("rk3").

#include <limits>
#include <string>
#include <string_view>

#include <feran/integrators/integrator.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// Kutta's third-order Runge–Kutta method (W. Kutta, "Beitrag zur näherungsweisen
/// Integration totaler Differentialgleichungen", Z. Math. Phys. 46, 435–453, 1901;
/// E. Hairer, S. P. Nørsett, G. Wanner, Solving Ordinary Differential Equations I,
/// 2nd ed., Springer 1993, Table II.1.1): c = (0, 1/2, 1), a21 = 1/2, a31 = −1,
/// a32 = 2, b = (1/6, 2/3, 1/6), applied to y = (x, v), y' = (v, M⁻¹·r(t, x, v)).
///
/// Stability: every three-stage third-order method has R(z) = 1 + z + z²/2 + z³/6,
/// which is stable on the imaginary axis for |z| ≤ √3. An undamped mode of frequency
/// ω therefore needs Δt ≤ √3/ω. start() compares settings.dt, and step() each Δt, with
/// √3/ω_max (ω_max = sys.highest_frequency()): above it the step is refused (ok =
/// false), or, with settings.allow_unstable_step, taken with a warning in the
/// report's message.
///
/// Each step costs three evaluations of r and three mass solves; the first stage uses
/// s.a, which must be M⁻¹·r(s.t, s.x, s.v) as start() and step() leave it (call start()
/// again after changing the state or the system).
class Rk3 final : public Integrator {
 public:
  /// Throws feran::Error for a non-positive settings.dt.
  explicit Rk3(const IntegratorSettings& settings);

  /// "rk3".
  std::string_view name() const override { return "rk3"; }
  /// Computes s.a and checks settings.dt against the stability limit √3/ω_max.
  StepReport start(SecondOrderSystem& sys, State& s) override;
  /// One step of exactly @p dt (refused above the stability limit unless allowed).
  StepReport step(SecondOrderSystem& sys, State& s, Real dt) override;

  /// The stability limit √3/ω_max [s] found by the last start() (infinity when
  /// ω_max = 0).
  Real stability_limit() const { return dt_limit_; }

 private:
  /// Empty when @p dt is within the limit; otherwise the refusal or warning text.
  std::string check_limit(Real dt) const;

  IntegratorSettings settings_;
  Real omega_max_ = 0.0;
  Real dt_limit_ = std::numeric_limits<Real>::infinity();
  Vector r_, x2_, v2_, a2_, x3_, v3_, a3_;  // reused work vectors
};

}  // namespace feran
