// Kutta's third-order Runge–Kutta method ("rk3"): convergence order and the stability
// limit √3/ω_max.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/integrators/rk3.hpp>
#include <feran/core/error.hpp>

#include "test_systems.hpp"

namespace feran {
namespace {

using test::DenseSystem;

// Forced two-DOF gyroscopic/circulatory oscillator over [0, 5] s, 40…1280 steps
// (Δt·ω_max ≤ 0.27, well inside the limit). Measured rates 3.011 3.015 3.009 3.005
// 3.003; the last two must be within 0.1 of 3 (MFEM's test_ode2 margin).
TEST(Rk3, ConvergesAtOrderThree) {
  const IntegratorSettings settings;
  const auto errors = test::linear_oscillator_errors([&] { return std::make_unique<Rk3>(settings); });
  const auto rates = test::observed_orders(errors);
  EXPECT_LT(errors.front(), 0.01);  // measured 3.5e-3 at 40 steps
  EXPECT_NEAR(rates[rates.size() - 2], 3.0, 0.1);
  EXPECT_NEAR(rates.back(), 3.0, 0.1);
}

State unit_displacement() {
  State s;
  s.x = Vector::Constant(1, 1.0);
  s.v = Vector::Zero(1);
  return s;
}

// ω = 10 rad/s: the limit is √3/10 = 0.1732 s.
constexpr Real omega = 10.0;
const Real limit = std::sqrt(3.0) / omega;

TEST(Rk3, RefusesAStepAboveTheStabilityLimit) {
  DenseSystem sys = test::undamped_sdof(omega);
  IntegratorSettings settings;
  settings.dt = 1.01 * limit;
  Rk3 integ(settings);
  State s = unit_displacement();
  const StepReport r = integ.start(sys, s);
  EXPECT_FALSE(r.ok);
  EXPECT_NEAR(integ.stability_limit(), limit, 1e-15);
  // The message states the step, the limit and ω_max.
  EXPECT_NE(r.message.find("0.174937"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("0.173205"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("omega_max = 10 rad/s"), std::string::npos) << r.message;
  // A step above the limit is refused too and leaves the state alone.
  const State before = s;
  const StepReport step = integ.step(sys, s, 1.01 * limit);
  EXPECT_FALSE(step.ok);
  EXPECT_EQ(s.x, before.x);
  EXPECT_EQ(s.t, before.t);
}

TEST(Rk3, AcceptsAStepBelowTheLimitSilently) {
  DenseSystem sys = test::undamped_sdof(omega);
  IntegratorSettings settings;
  settings.dt = 0.99 * limit;
  Rk3 integ(settings);
  State s = unit_displacement();
  const StepReport r = integ.start(sys, s);
  EXPECT_TRUE(r.ok);
  EXPECT_TRUE(r.message.empty()) << r.message;
}

TEST(Rk3, AllowsAnUnstableStepWithAWarning) {
  DenseSystem sys = test::undamped_sdof(omega);
  IntegratorSettings settings;
  settings.dt = 1.1 * limit;
  settings.allow_unstable_step = true;
  Rk3 integ(settings);
  State s = unit_displacement();
  const StepReport r = integ.start(sys, s);
  EXPECT_TRUE(r.ok);
  EXPECT_NE(r.message.find("exceeds the stability limit"), std::string::npos) << r.message;
  const StepReport step = integ.step(sys, s, settings.dt);
  EXPECT_TRUE(step.ok);
  EXPECT_FALSE(step.message.empty());
}

// The limit is real: |R(iωΔt)| < 1 below it and > 1 above. 1000 steps at 0.9× the
// limit decay (|R| = 0.952, measured |x| = 7e-24), at 1.1× they grow (|R| = 1.109,
// measured |x| = 6e44).
TEST(Rk3, StabilityLimitIsSharp) {
  for (const Real factor : {0.9, 1.1}) {
    DenseSystem sys = test::undamped_sdof(omega);
    IntegratorSettings settings;
    settings.dt = factor * limit;
    settings.allow_unstable_step = true;
    Rk3 integ(settings);
    State s = unit_displacement();
    ASSERT_TRUE(integ.start(sys, s).ok);
    for (int k = 0; k < 1000; ++k) integ.step(sys, s, settings.dt);
    const Real amplitude = std::hypot(s.x(0), s.v(0) / omega);
    if (factor < 1.0)
      EXPECT_LT(amplitude, 1.0) << "0.9 x limit";
    else
      EXPECT_GT(amplitude, 1e30) << "1.1 x limit";
  }
}

TEST(Rk3, RejectsANonPositiveStep) {
  IntegratorSettings settings;
  settings.dt = 0.0;
  EXPECT_THROW(Rk3{settings}, Error);
}

}  // namespace
}  // namespace feran
