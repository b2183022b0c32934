#pragma once
/// @file
/// Newmark's method with Newton iterations; its average-acceleration preset is the
/// trapezoidal rule ("trapezoidal").

#include <string_view>

#include <feran/integrators/integrator.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// The two parameters of Newmark's method.
struct NewmarkParameters {
  Real beta = 0.25;  ///< β > 0 (β = 0, the explicit central difference, is not supported)
  Real gamma = 0.5;  ///< γ; second order only for γ = 1/2

  /// Average (constant) acceleration, β = 1/4, γ = 1/2: the trapezoidal rule,
  /// unconditionally stable and free of numerical dissipation.
  static NewmarkParameters average_acceleration() { return {0.25, 0.5}; }
  /// Linear acceleration, β = 1/6, γ = 1/2: second order, conditionally stable
  /// (Δt·ω ≤ 2√3).
  static NewmarkParameters linear_acceleration() { return {1.0 / 6.0, 0.5}; }
};

/// Newmark's method (N. M. Newmark, "A method of computation for structural
/// dynamics", J. Eng. Mech. Div. ASCE 85 (EM3), 67–94, 1959; paper eqs. 8–9), solved
/// for x_{n+1} by Newton iterations on the full residual
///   R(x_{n+1}) = M·a_{n+1} − r(t_{n+1}, x_{n+1}, v_{n+1}),
///   a_{n+1} = (x_{n+1} − x_n − Δt·v_n)/(βΔt²) − (1/(2β) − 1)·a_n,
///   v_{n+1} = v_n + Δt·((1 − γ)·a_n + γ·a_{n+1}),
/// with the Newton matrix S = M/(βΔt²) + γ/(βΔt)·D_T + K_T and the exact Jacobian.
///
/// Newton strategy (modified Newton while it converges fast): a step starts with the
/// factorisation of S left by the previous step when Δt is unchanged; when a
/// correction is not at least 5 times smaller than the one before
/// (‖δ_k‖ > 0.2·‖δ_{k−1}‖), the Jacobian is re-evaluated and S refactorised at every
/// further iteration of that step (full Newton). Converged when
/// ‖δx‖ ≤ newton_tol·(1 + ‖x‖) (Euclidean norms), or after the first correction when
/// the system reports its factorised Jacobian exact at t_{n+1} for a linear r
/// (SecondOrderSystem::tangent_exact_at: a linear rotor at constant speed), since that
/// correction solves the linear step equations directly. After start() the integrator
/// assumes that nothing else sets the system's Jacobian or factorises its tangent
/// between steps; call start() again if something does.
///
/// s.a is Newmark's acceleration, which satisfies M·a = r to the Newton tolerance.
/// A failed step (no convergence within newton_max_iterations, singular S, or a
/// non-finite correction) leaves the state unchanged and reports ok = false.
class Newmark final : public Integrator {
 public:
  /// Throws feran::Error for β ≤ 0, newton_tol ≤ 0 or newton_max_iterations < 1.
  explicit Newmark(const IntegratorSettings& settings,
                   NewmarkParameters parameters = NewmarkParameters::average_acceleration());

  /// "trapezoidal" for average acceleration, "newmark" otherwise.
  std::string_view name() const override;
  /// Computes s.a from M·a_0 = r(t_0, x_0, v_0) and forgets any kept factorisation.
  StepReport start(SecondOrderSystem& sys, State& s) override;
  /// One step of exactly @p dt; reports the Newton iterations and factorisations.
  StepReport step(SecondOrderSystem& sys, State& s, Real dt) override;

  /// The parameters in use.
  const NewmarkParameters& parameters() const { return parameters_; }

 private:
  /// Newton's convergence threshold for the correction of the step from @p x_old:
  /// newton_tol·‖x_{n+1} − x_n‖ + 16·ε·‖x_{n+1}‖ (ε the machine epsilon).
  Real tolerance(const Vector& x_old) const;

  IntegratorSettings settings_;
  NewmarkParameters parameters_;
  bool factored_ = false;  // the system holds a factorisation of S for dt_factored_
  Real dt_factored_ = 0.0;
  Vector x1_, v1_, a1_, r_, ma_, residual_, delta_;  // reused work vectors
};

}  // namespace feran
