#pragma once
/// @file
/// Time integrators of M·x'' = r(t, x, v), chosen by name (registry.hpp).

#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <feran/integrators/second_order_system.hpp>
#include <feran/core/types.hpp>

namespace feran {

/// Settings shared by the integrators; each uses the ones that concern it.
struct IntegratorSettings {
  Real dt = 1e-4;  ///< fixed step [s]; initial step of the adaptive method
  // Adaptive step control (ros34pw2): the root mean square over all displacements and
  // velocities of error / (abs_tol + rel_tol·|y|) stays ≤ 1. The defaults give the
  // paper's run-ups' peaks to about 5e-5 relative (measured, docs/theory/time_integration.md).
  Real rel_tol = 1e-5;
  Real abs_tol = 1e-8;
  Real dt_min = 1e-12;
  Real dt_max = std::numeric_limits<Real>::infinity();
  // Newton iterations (trapezoidal): converged when the correction's norm is below
  // newton_tol·‖x_{n+1} − x_n‖ + 16·ε·‖x_{n+1}‖: relative to the step's own change,
  // floored at the state's round-off; at most newton_max_iterations.
  Real newton_tol = 1e-10;
  int newton_max_iterations = 25;
  /// rk3: warn instead of refusing a step above the stability limit.
  bool allow_unstable_step = false;
  /// W-methods: include the nonlinear forces' tangents in the Jacobian.
  bool exact_jacobian = true;
  /// W-methods: refresh the Jacobian (and factorisation) every this many steps
  /// (1: every step; larger: a lagged Jacobian, which keeps a W-method's order). An
  /// adaptive step rejected with a lagged Jacobian is retried with a fresh one.
  int jacobian_interval = 10;
};

/// What a step did.
struct StepReport {
  bool ok = true;
  Real dt = 0.0;       ///< the step taken [s]
  Real dt_next = 0.0;  ///< the step proposed for the next one (adaptive) [s]
  int iterations = 0;  ///< Newton iterations (trapezoidal)
  int rejected = 0;    ///< rejected trial steps (adaptive)
  int factorizations = 0;
  std::string message;  ///< why not ok, or a warning
};

/// A one-step method for M·x'' = r(t, x, v).
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string_view name() const = 0;
  /// True when step() chooses its own step size from the tolerances.
  virtual bool adaptive() const { return false; }
  /// Prepares integration from @p s (computes s.a; rk3 checks its stability limit).
  /// A report with ok = false refuses the run and says why.
  virtual StepReport start(SecondOrderSystem& sys, State& s) = 0;
  /// Advances @p s by one step. Fixed-step methods take exactly @p dt; the adaptive
  /// method tries @p dt, may take less, and proposes the next step.
  virtual StepReport step(SecondOrderSystem& sys, State& s, Real dt) = 0;
};

namespace detail {
/// The common start of every integrator: checks that @p s matches the system's size
/// and computes s.a from M·a = r(t, x, v), using @p r as work space. A report with
/// ok = false names @p method and the mismatch.
StepReport initial_acceleration(std::string_view method, SecondOrderSystem& sys, State& s, Vector& r);
}  // namespace detail

/// The integrator named @p name ("trapezoidal", "rk3", "wolfbrandt", "ros34pw2").
/// Throws feran::Error for an unknown name, listing the known ones.
std::unique_ptr<Integrator> make_integrator(const std::string& name, const IntegratorSettings& settings);
/// The names make_integrator() knows.
std::vector<std::string> integrator_names();

}  // namespace feran
