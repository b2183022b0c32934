#include <feran/integrators/newmark.hpp>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// Modified Newton keeps the old matrix while each correction is at least this much
// smaller than the one before; a slower contraction switches to full Newton.
constexpr Real max_contraction = 0.2;

// The floor of the convergence test, in units of the state's round-off ε·‖x‖: a
// correction that small is noise of the solve itself (see tolerance()).
constexpr Real round_off_ulps = 16.0;

}  // namespace

Newmark::Newmark(const IntegratorSettings& settings, NewmarkParameters parameters)
    : settings_(settings), parameters_(parameters) {
  if (!(parameters_.beta > 0.0)) throw Error(fmt::format("Newmark: beta must be positive (got {})", parameters_.beta));
  if (!(settings_.newton_tol > 0.0))
    throw Error(fmt::format("Newmark: newton_tol must be positive (got {})", settings_.newton_tol));
  if (settings_.newton_max_iterations < 1)
    throw Error(
        fmt::format("Newmark: newton_max_iterations must be at least 1 (got {})", settings_.newton_max_iterations));
}

std::string_view Newmark::name() const {
  const NewmarkParameters avg = NewmarkParameters::average_acceleration();
  return parameters_.beta == avg.beta && parameters_.gamma == avg.gamma ? "trapezoidal" : "newmark";
}

StepReport Newmark::start(SecondOrderSystem& sys, State& s) {
  StepReport report = detail::initial_acceleration(name(), sys, s, r_);
  if (!report.ok) return report;
  factored_ = false;
  return report;
}

Real Newmark::tolerance(const Vector& x_old) const {
  // Relative to what the step changes, with a floor at the state's round-off for a
  // step that changes (almost) nothing: an absolute test (as once, 1e-10·(1 + ‖x‖), in
  // metres) accepted corrections comparable to a slowly moving state's whole increment.
  return settings_.newton_tol * (x1_ - x_old).norm() +
         round_off_ulps * std::numeric_limits<Real>::epsilon() * x1_.norm() + std::numeric_limits<Real>::min();
}

StepReport Newmark::step(SecondOrderSystem& sys, State& s, Real dt) {
  StepReport report;
  report.dt = dt;
  report.dt_next = dt;
  const Real beta = parameters_.beta;
  const Real gamma = parameters_.gamma;
  const Real t1 = s.t + dt;
  const Real c_a = 1.0 / (beta * dt * dt);
  const Real c_v = gamma / (beta * dt);
  const Real a_old = 1.0 / (2.0 * beta) - 1.0;  // coefficient of a_n in a_{n+1}

  // Predictor x_n + Δt·v_n + Δt²/2·a_n, for which Newmark's a_{n+1} equals a_n.
  x1_ = s.x + dt * s.v + (0.5 * dt * dt) * s.a;
  // Where a refactorisation costs about one iteration (banded), a step starts from a
  // tangent at its predicted state: exact for a linear model on a speed ramp (one
  // solve, where the kept tangent needs four to six iterations), and 2–3 iterations
  // instead of 6–8 for journal bearings and friction (docs/theory/time_integration.md).
  bool refresh = !factored_ || dt != dt_factored_ || (!sys.tangent_exact_at(t1) && sys.refresh_pays_at(t1));
  bool full_newton = false;
  Real previous_norm = 0.0;
  Real norm = 0.0;
  for (int k = 1; k <= settings_.newton_max_iterations; ++k) {
    a1_ = c_a * (x1_ - s.x - dt * s.v) - a_old * s.a;
    v1_ = s.v + dt * ((1.0 - gamma) * s.a + gamma * a1_);
    if (refresh || full_newton) {
      sys.set_jacobian(t1, x1_, v1_, true);
      ++report.factorizations;
      if (!sys.factor_tangent(1.0, c_v, c_a)) {
        factored_ = false;
        report.ok = false;
        report.iterations = k;
        report.message = fmt::format("{}: singular Newton matrix at t = {:.9g} (dt = {:.6g})", name(), t1, dt);
        return report;
      }
      factored_ = true;
      dt_factored_ = dt;
      refresh = false;
    }
    sys.rhs(t1, x1_, v1_, r_);
    sys.mass_times(a1_, ma_);
    residual_ = r_ - ma_;  // −R
    sys.solve_tangent(residual_, delta_);
    x1_ += delta_;
    norm = delta_.norm();
    report.iterations = k;
    if (!std::isfinite(norm)) break;
    // A linear system with its exact Jacobian factorised: the first correction
    // solves the step's equations exactly, and a second iteration (a residual and
    // a solve, half the step's cost) would only confirm it.
    const bool solved = k == 1 && sys.tangent_exact_at(t1);
    if (solved || norm <= tolerance(s.x)) {
      a1_ = c_a * (x1_ - s.x - dt * s.v) - a_old * s.a;
      v1_ = s.v + dt * ((1.0 - gamma) * s.a + gamma * a1_);
      s.t = t1;
      s.x.swap(x1_);
      s.v.swap(v1_);
      s.a.swap(a1_);
      return report;
    }
    if (k >= 2 && norm > max_contraction * previous_norm) full_newton = true;
    previous_norm = norm;
  }
  report.ok = false;
  report.message = fmt::format(
      "{}: Newton did not converge in {} iteration(s) at t = {:.9g} (dt = {:.6g}): last correction "
      "norm {:.3e}, tolerance {:.3e}",
      name(), report.iterations, t1, dt, norm, tolerance(s.x));
  return report;
}

}  // namespace feran
