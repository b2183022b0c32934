#include <feran/integrators/rk3.hpp>

#include <cmath>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

namespace {

// Imaginary-axis stability boundary of R(z) = 1 + z + z²/2 + z³/6:
// |R(iy)|² = 1 − y⁴/12 + y⁶/36 ≤ 1 ⇔ y ≤ √3.
const Real imaginary_axis_limit = std::sqrt(3.0);

}  // namespace

Rk3::Rk3(const IntegratorSettings& settings) : settings_(settings) {
  if (!(settings_.dt > 0.0)) throw Error(fmt::format("rk3: dt must be positive (got {})", settings_.dt));
}

std::string Rk3::check_limit(Real dt) const {
  if (!(dt > dt_limit_)) return {};
  return fmt::format(
      "rk3: time step {:.6g} s exceeds the stability limit sqrt(3)/omega_max = {:.6g} s "
      "(omega_max = {:.6g} rad/s = {:.6g} Hz){}",
      dt, dt_limit_, omega_max_, rad_to_hz(omega_max_),
      settings_.allow_unstable_step ? "; continuing because unstable steps are allowed, expect growth"
                                    : "; reduce the step or choose an implicit integrator");
}

StepReport Rk3::start(SecondOrderSystem& sys, State& s) {
  StepReport report = detail::initial_acceleration("rk3", sys, s, r_);
  if (!report.ok) return report;

  omega_max_ = sys.highest_frequency();
  dt_limit_ = omega_max_ > 0.0 ? imaginary_axis_limit / omega_max_ : std::numeric_limits<Real>::infinity();
  report.dt = settings_.dt;
  report.dt_next = settings_.dt;
  report.message = check_limit(settings_.dt);
  report.ok = report.message.empty() || settings_.allow_unstable_step;
  return report;
}

StepReport Rk3::step(SecondOrderSystem& sys, State& s, Real dt) {
  StepReport report;
  report.dt = dt;
  report.dt_next = dt;
  report.message = check_limit(dt);
  if (!report.message.empty() && !settings_.allow_unstable_step) {
    report.ok = false;
    return report;
  }
  const Real t = s.t;
  // Stage 1 is (v_n, a_n); stage 2 at t + h/2, y + h/2·k1.
  x2_ = s.x + (0.5 * dt) * s.v;
  v2_ = s.v + (0.5 * dt) * s.a;
  sys.rhs(t + 0.5 * dt, x2_, v2_, r_);
  sys.solve_mass(r_, a2_);
  // Stage 3 at t + h, y − h·k1 + 2h·k2.
  x3_ = s.x + dt * (2.0 * v2_ - s.v);
  v3_ = s.v + dt * (2.0 * a2_ - s.a);
  sys.rhs(t + dt, x3_, v3_, r_);
  sys.solve_mass(r_, a3_);
  // y_{n+1} = y_n + h/6·(k1 + 4k2 + k3).
  s.x += (dt / 6.0) * (s.v + 4.0 * v2_ + v3_);
  s.v += (dt / 6.0) * (s.a + 4.0 * a2_ + a3_);
  s.t = t + dt;
  sys.rhs(s.t, s.x, s.v, r_);
  sys.solve_mass(r_, s.a);
  return report;
}

}  // namespace feran
