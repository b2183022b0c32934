// Run-up (transient) analysis against closed forms, eigenvalues and the harmonic
// response, on a Jeffcott rotor: a point mass m on an isotropic spring k.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <feran/analyses/response/harmonic_response.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/transient/rotor_system.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>

#include "test_models.hpp"

namespace feran::test_runup {
namespace {

constexpr Real m = test::runup_mass, k = test::runup_stiffness;
const Real wn = std::sqrt(k / m);  // 132.6 rad/s

Model jeffcott(Real ca, Real ci, Real unbalance = 0.0, Real friction = 0.0) {
  return test::runup_jeffcott(ca, ci, unbalance, friction);
}

// At constant speed the transient settles on the harmonic (steady-state) response:
// after 60 decay times the orbit radius equals |R| of the frequency-domain solution.
// Tolerance 2e-5: the trapezoidal rule's amplitude error for a forced response is
// O((Ωh)²/12) = 1.6e-6 at Ωh = 0.0044, plus the decayed transient (e^{-60}).
TEST(Runup, ConstantSpeedSettlesOnTheSteadyState) {
  const Model model = jeffcott(400.0, 0.0, 1e-3);
  const Real speed = 0.7 * wn;
  HarmonicOptions h;
  h.speeds = {speed};
  h.probes = {0};
  const Real R = run_harmonic_response(model, h).probes[0].orbit[0].major;
  TransientOptions t;
  t.profile = SpeedProfile::constant(speed);
  const Real decay = 400.0 / (2 * m);  // 1/s
  t.duration = 60.0 / decay;
  t.settings.dt = 2 * pi / speed / 1000;
  t.output_interval = 1e-3;
  t.probes = {0};
  for (const char* name : {"trapezoidal", "wolfbrandt", "ros34pw2"}) {
    t.integrator = name;
    const TransientResult r = run_transient(model, t);
    ASSERT_TRUE(r.info.converged()) << r.info.message;
    EXPECT_NEAR(r.samples.back().magnitude[0], R, 2e-5 * R) << name;
    // Linear at constant speed: the trapezoidal rule's first Newton correction
    // solves each step (RotorSystem::tangent_exact_at); one factorisation, and one
    // more for the shortened last step.
    if (std::string(name) == "trapezoidal") {
      EXPECT_EQ(r.newton_iterations, r.steps);
      EXPECT_LE(r.factorizations, 2);
    }
  }
}

// RotorSystem reports its Jacobian exact only where one Newton correction solves a
// step: a linear model at the speed the Jacobian was set at. During a run-up the
// speed (and with it the gyroscopic and speed-dependent terms) moves on; friction
// makes the model nonlinear at any speed.
TEST(Runup, TangentIsExactOnlyForALinearModelAtItsSpeed) {
  const Model linear = jeffcott(400.0, 0.0, 1e-3);
  RotorSystem constant(linear, SpeedProfile::constant(0.5 * wn));
  const Vector zero = Vector::Zero(constant.size());
  EXPECT_FALSE(constant.tangent_exact_at(0.0));  // no Jacobian set yet
  constant.set_jacobian(0.0, zero, zero, true);
  EXPECT_TRUE(constant.tangent_exact_at(0.0));
  EXPECT_TRUE(constant.tangent_exact_at(1.0));
  RotorSystem ramp(linear, SpeedProfile::ramp(0.0, 2 * wn, 1.0));
  ramp.set_jacobian(0.5, zero, zero, true);
  EXPECT_TRUE(ramp.tangent_exact_at(0.5));
  EXPECT_FALSE(ramp.tangent_exact_at(0.5001));
  const Model dry = jeffcott(400.0, 0.0, 1e-3, 5.0);
  RotorSystem friction(dry, SpeedProfile::constant(1.5 * wn));
  friction.set_jacobian(0.0, zero, zero, true);
  EXPECT_FALSE(friction.tangent_exact_at(0.0));
}

// Rotating (internal) damping c_i with external c_a: a free whirl decays below the
// threshold speed ω_n(1 + c_a/c_i) and grows above it, at the rate −Re p of the
// forward eigenvalue. The rate is measured from |r| over many whirl periods
// (|r| of a single circular mode is e^{−Re(p)·t} exactly). 1e-4: step error of
// the trapezoidal rule in the growth exponent, (ωh)²/12 ~ 1e-6 per unit exponent.
TEST(Runup, InternalDampingGrowthMatchesTheEigenvalue) {
  const Real ca = 100.0, ci = 300.0;
  const Model model = jeffcott(ca, ci);
  for (Real speed : {0.8 * wn * (1 + ca / ci), 1.3 * wn * (1 + ca / ci)}) {
    Real rate = 0;
    for (const Mode& mode : run_modal(model, speed).modes)
      if (mode.whirl == Whirl::forward) rate = mode.eigenvalue.real();
    TransientOptions t;
    t.profile = SpeedProfile::constant(speed);
    t.duration = 1.0;
    t.settings.dt = 2e-5;
    t.output_interval = 0.01;
    t.probes = {0};
    // A forward circular whirl of 1 mm: the forward mode alone.
    t.initial_displacement = Vector::Zero(model.n_dofs());
    t.initial_velocity = Vector::Zero(model.n_dofs());
    t.initial_displacement(global_dof(0, Dof::v)) = 1e-3;
    Real omega = 0;
    for (const Mode& mode : run_modal(model, speed).modes)
      if (mode.whirl == Whirl::forward) omega = mode.eigenvalue.imag();
    t.initial_velocity(global_dof(0, Dof::v)) = rate * 1e-3;
    t.initial_velocity(global_dof(0, Dof::w)) = omega * 1e-3;
    const TransientResult r = run_transient(model, t);
    ASSERT_TRUE(r.info.converged()) << r.info.message;
    const Real measured =
        std::log(r.samples.back().magnitude[0] / r.samples[10].magnitude[0]) / (r.samples.back().t - r.samples[10].t);
    EXPECT_NEAR(measured, rate, 1e-4 * std::abs(rate) + 1e-6) << "speed/threshold " << speed / (wn * (1 + ca / ci));
    EXPECT_EQ(measured > 0, speed > wn * (1 + ca / ci));
  }
}

// Coulomb friction between rotor and shaft above the critical speed drives a forward
// whirl at ω_n whose radius balances friction and external damping:
// c_a·ω_n·R = F_c0 (the friction force is tangential, forward, of constant size).
// Tolerance 1 %: the regularisation (ε = 1e-5 m/s against a relative speed
// (Ω − ω_n)·R ≈ 0.3 m/s) and the residual transient.
TEST(Runup, CoulombFrictionWhirlRadius) {
  const Real ca = 300.0, F = 20.0;
  const Model model = jeffcott(ca, 0.0, 0.0, F);
  const TransientResult r = run_transient(model, test::friction_whirl_run(model, 5e-5));
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  const Real R = F / (ca * wn);
  EXPECT_NEAR(r.samples.back().magnitude[0], R, 0.01 * R);
}

// Passing a critical speed in a run-up: the peak stays below the steady-state peak
// and comes later, the more so the faster the run-up (Lewis 1932; Gasch et al.,
// Rotordynamik, ch. 10).
TEST(Runup, FasterRunUpsPeakLowerAndLater) {
  const Model model = jeffcott(150.0, 0.0, 1e-3);
  HarmonicOptions h;
  for (int i = 0; i <= 4000; ++i) h.speeds.push_back(2.0 * wn * i / 4000);
  h.probes = {0};
  const ResponseSummary s = summarize(run_harmonic_response(model, h));
  const Real steady_peak = s.probe_peaks[0].value;
  const Real steady_speed = h.speeds[static_cast<std::size_t>(s.probe_peaks[0].point)];
  Real last_peak = steady_peak, last_speed = steady_speed;
  for (Real ramp_time : {8.0, 2.0, 0.5}) {
    TransientOptions t;
    t.profile = SpeedProfile::ramp(0.0, 2.0 * wn, ramp_time);
    t.duration = ramp_time;
    t.settings.dt = 1e-4;
    t.probes = {0};
    const TransientResult r = run_transient(model, t);
    ASSERT_TRUE(r.info.converged()) << r.info.message;
    EXPECT_LT(r.envelopes[0].peak, last_peak) << "ramp " << ramp_time << " s";
    EXPECT_GT(r.envelopes[0].peak_speed, last_speed) << "ramp " << ramp_time << " s";
    last_peak = r.envelopes[0].peak;
    last_speed = r.envelopes[0].peak_speed;
  }
}

// The integrators agree on the same run-up through the critical speed (Jeffcott,
// 0 → 2ω_n in 1 s): the sampled |r| histories differ by less than 1e-3 of the peak.
// The trapezoidal and Wolfbrandt steps (Δt = 2e-5 s, ω_n·Δt = 2.7e-3) carry phase
// errors of (ωΔt)²/12 per radian, about 1e-4 rad after the 130 rad of the run;
// rk3 and ros34pw2 (tolerance 1e-8) are more accurate still.
TEST(Runup, IntegratorsAgree) {
  const Model model = jeffcott(150.0, 0.0, 1e-3);
  TransientOptions t;
  t.profile = SpeedProfile::ramp(0.0, 2.0 * wn, 1.0);
  t.duration = 1.0;
  t.settings.dt = 2e-5;
  t.settings.rel_tol = 1e-8;
  t.settings.abs_tol = 1e-12;
  t.output_interval = 1e-3;
  t.probes = {0};
  t.integrator = "trapezoidal";
  const TransientResult ref = run_transient(model, t);
  ASSERT_TRUE(ref.info.converged());
  for (const char* name : {"rk3", "wolfbrandt", "ros34pw2"}) {
    t.integrator = name;
    const TransientResult r = run_transient(model, t);
    ASSERT_TRUE(r.info.converged()) << name << ": " << r.info.message;
    ASSERT_EQ(r.samples.size(), ref.samples.size());
    Real worst = 0;
    for (std::size_t i = 0; i < r.samples.size(); ++i)
      worst = std::max(worst, std::abs(r.samples[i].magnitude[0] - ref.samples[i].magnitude[0]));
    EXPECT_LT(worst, 1e-3 * ref.envelopes[0].peak) << name;
    EXPECT_NEAR(r.envelopes[0].peak, ref.envelopes[0].peak, 1e-3 * ref.envelopes[0].peak) << name;
  }
}

}  // namespace
}  // namespace feran::test_runup
