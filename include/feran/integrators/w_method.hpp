#pragma once
/// @file
/// Linearly implicit Runge–Kutta methods of W type (Rosenbrock-W): "wolfbrandt"
/// (order 2, fixed step) and "ros34pw2" (order 3, adaptive), presets of one class.

#include <string>
#include <string_view>
#include <vector>

#include <feran/integrators/integrator.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// Coefficients of an s-stage W-method in the form
///   (I − hγT)·k_i = h·f(t_n + c_i·h, y_n + Σ_{j<i} α_ij·k_j) + h·T·Σ_{j<i} γ_ij·k_j,
///   y_{n+1} = y_n + Σ b_i·k_i,   ŷ_{n+1} = y_n + Σ b̂_i·k_i (embedded),
/// c_i = Σ_j α_ij, T any matrix (ideally ≈ ∂f/∂y). This is the form of Hairer & Wanner
/// (Solving ODEs II, sec. IV.7) and of PETSc's TSROSW, whose Γ has γ on the diagonal
/// and the γ_ij below it.
struct WTableau {
  std::string name;        ///< registry name
  Real gamma = 0.0;        ///< diagonal γ of Γ
  Matrix alpha;            ///< s×s, strictly lower triangular α_ij
  Matrix gamma_ij;         ///< s×s, strictly lower triangular γ_ij (Γ without its diagonal)
  Vector b;                ///< weights of the solution
  Vector b_hat;            ///< weights of the embedded solution (empty: none)
  int order = 0;           ///< order of the solution for any T (W-order)
  int embedded_order = 0;  ///< order of the embedded solution (0: none)

  /// Number of stages s.
  Index stages() const { return b.size(); }

  /// Steihaug–Wolfbrandt's two-stage W-method of order 2 (T. Steihaug, A. Wolfbrandt,
  /// "An attempt to avoid exact Jacobian and nonlinear equations in the numerical
  /// solution of stiff differential equations", Math. Comp. 33 (146), 521–534, 1979):
  /// γ = 1 − √2/2, α21 = 2/3, γ21 = −4γ/3, b = (1/4, 3/4). L-stable (R(∞) = 0); no
  /// embedded method.
  static WTableau wolfbrandt();
  /// ROS34PW2 (J. Rang, L. Angermann, "New Rosenbrock W-methods of order 3 for
  /// partial differential algebraic equations of index 1", BIT 45, 761–787, 2005):
  /// 4 stages, W-order 3, L-stable, embedded order 2; coefficients as in PETSc's
  /// TSROSWRA34PW2 (src/ts/impls/rosw/rosw.c).
  static WTableau ros34pw2();
};

/// A W-method applied to M·x'' = r(t, x, v) as y = (x, v), y' = (v, M⁻¹·r), with
/// T = c·[[0, I], [−M⁻¹K_T, −M⁻¹D_T]] and the Jacobian approximation K_T, D_T of the
/// system. Each stage is one condensed n×n solve (docs/theory/time_integration.md):
///   (M + h_Tγ·D_T + h_T²γ²·K_T)·k_v = h·r(Y_i) − h_T·D_T·g_v − K_T·(h_T·g_q + h_Tγ·r_q),
///   k_q = r_q + h_Tγ·k_v,   r_q = h·V_i + h_T·g_v,   g = Σ_{j<i} γ_ij·k_j,
/// where h_T = c·h is the step the factorisation was made for. No Newton iteration.
///
/// Time is treated autonomously: stages are evaluated at t_n + c_i·h and ∂r/∂t is left
/// out (a zero column of T, allowed because the order holds for any T).
///
/// Jacobian and factorisation reuse: the Jacobian is set (set_jacobian(t_n, x_n, v_n,
/// settings.exact_jacobian)) at the first step after start() and then every
/// settings.jacobian_interval steps; the matrix is refactorised when the Jacobian was
/// set or when h differs from h_T by more than 3 % (the W-method stays consistent for
/// any c, so a factorisation made for a slightly different step is still exact in
/// order). After a rejected step a Jacobian older than the current state is re-set.
/// After start() the integrator assumes that nothing else sets the system's Jacobian
/// or factorises its tangent between steps; call start() again if something does.
///
/// Fixed step (adaptive = false): step() takes exactly Δt. Adaptive (needs b̂): the
/// error estimate e = Σ(b_i − b̂_i)·k_i is measured in the maximum norm scaled
/// component-wise by abs_tol + rel_tol·max(|y_n|, |y_{n+1}|) over x and v; the step is
/// accepted when that is ≤ 1, and the next one is h·min(5, max(0.2, 0.9·err^(−1/3)))
/// (no growth right after a rejection), clipped to [dt_min, dt_max]. A rejected try is
/// repeated with the smaller step; a rejection at dt_min fails the step (ok = false)
/// and leaves the state unchanged.
///
/// s.a is M⁻¹·r at the new state (one more evaluation of r per step, which is also the
/// first stage of the next step). s.a must be as start() and step() leave it.
class WMethod final : public Integrator {
 public:
  /// Throws feran::Error for inconsistent coefficients, for adaptive without an
  /// embedded method, or for bad settings (dt ≤ 0, jacobian_interval < 1; adaptive:
  /// negative or both zero tolerances, dt_min ≤ 0 or dt_min > dt_max).
  WMethod(WTableau tableau, const IntegratorSettings& settings, bool adaptive);

  /// The tableau's name.
  std::string_view name() const override { return tableau_.name; }
  /// True for the adaptive variant (chosen at construction).
  bool adaptive() const override { return adaptive_; }
  /// Computes s.a and forgets any kept Jacobian and factorisation.
  StepReport start(SecondOrderSystem& sys, State& s) override;
  /// One step: exactly @p dt (fixed), or tries min(@p dt, dt_max) and reduces it until
  /// the error test passes (adaptive); reports the step taken, the next step, the
  /// rejected tries and the factorisations.
  StepReport step(SecondOrderSystem& sys, State& s, Real dt) override;

  /// The coefficients in use.
  const WTableau& tableau() const { return tableau_; }

 private:
  /// Sets the Jacobian and factorises as the reuse rules require; false when singular.
  bool prepare(SecondOrderSystem& sys, const State& s, Real h, bool after_rejection, StepReport& report);
  /// Computes the stages for step @p h into x_new_, v_new_ (and the error estimate).
  void stages(SecondOrderSystem& sys, const State& s, Real h);
  /// Scaled maximum norm of the error estimate.
  Real error_norm(const State& s) const;
  /// Moves x_new_, v_new_ into @p s and computes s.a.
  void commit(SecondOrderSystem& sys, State& s, Real h);

  WTableau tableau_;
  IntegratorSettings settings_;
  bool adaptive_;
  Vector c_;        // stage times c_i
  Vector b_error_;  // b − b̂

  bool jacobian_set_ = false;
  bool jacobian_current_ = false;  // set at the current state
  long steps_since_jacobian_ = 0;
  bool factored_ = false;
  Real h_factored_ = 0.0;

  std::vector<Vector> kq_, kv_;  // stage increments of x and v
  Vector yq_, yv_, gq_, gv_, r_, rhs_, work_, work2_, x_new_, v_new_, eq_, ev_;
};

}  // namespace feran
