// Newmark's method with Newton iterations ("trapezoidal" = average acceleration):
// convergence order, energy conservation, Newton iterations and their failure.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/integrators/newmark.hpp>
#include <feran/core/error.hpp>

#include "test_systems.hpp"

namespace feran {
namespace {

using test::DenseSystem;

// Observed order on the forced two-DOF gyroscopic/circulatory oscillator over [0, 5] s,
// 40…1280 steps. Measured rates: 2.011 2.003 2.001 2.000 2.000 (average acceleration),
// 2.002 2.001 2.000 2.000 2.000 (linear acceleration). The last two must be within 0.1
// of 2, the margin MFEM's test_ode2 allows for the pre-asymptotic range.
void expect_order_two(NewmarkParameters p) {
  const IntegratorSettings settings;
  const auto errors = test::linear_oscillator_errors([&] { return std::make_unique<Newmark>(settings, p); });
  const auto rates = test::observed_orders(errors);
  EXPECT_LT(errors.front(), 0.05);  // measured 1.5e-2 (avg.), 9.2e-3 (lin.) at 40 steps
  EXPECT_NEAR(rates[rates.size() - 2], 2.0, 0.1);
  EXPECT_NEAR(rates.back(), 2.0, 0.1);
}

TEST(Newmark, AverageAccelerationConvergesAtOrderTwo) { expect_order_two(NewmarkParameters::average_acceleration()); }

TEST(Newmark, LinearAccelerationConvergesAtOrderTwo) { expect_order_two(NewmarkParameters::linear_acceleration()); }

// Nonlinear oscillator (Duffing term, regularised friction) over [0, 4] s against
// test::nonlinear_reference (error 2.5e-13, far below the finest error here, 1.4e-6).
// Measured rates 2.000 2.000 2.000 2.000 1.996.
TEST(Newmark, TrapezoidalConvergesAtOrderTwoOnANonlinearProblem) {
  DenseSystem sys = test::nonlinear_oscillator();
  const State s0 = test::initial_state(2);
  const State ref = test::nonlinear_reference(s0);
  const IntegratorSettings settings;
  const auto errors =
      test::errors_at_halved_steps([&] { return std::make_unique<Newmark>(settings); }, sys, s0, 4.0, ref.x, ref.v);
  const auto rates = test::observed_orders(errors);
  EXPECT_NEAR(rates[rates.size() - 2], 2.0, 0.1);
  EXPECT_NEAR(rates.back(), 2.0, 0.1);
}

TEST(Newmark, NameOfThePresets) {
  const IntegratorSettings settings;
  EXPECT_EQ(Newmark(settings).name(), "trapezoidal");
  EXPECT_EQ(Newmark(settings, NewmarkParameters::linear_acceleration()).name(), "newmark");
  EXPECT_FALSE(Newmark(settings).adaptive());
}

TEST(Newmark, StartComputesTheInitialAcceleration) {
  DenseSystem sys = test::gyroscopic_oscillator();
  State s = test::initial_state(2);
  Newmark integ{IntegratorSettings{}};
  ASSERT_TRUE(integ.start(sys, s).ok);
  Vector r;
  sys.rhs(s.t, s.x, s.v, r);
  // M·a_0 = r to round-off (entries of order 1).
  EXPECT_LT((sys.M * s.a - r).norm(), 1e-14);
}

TEST(Newmark, StartRefusesAStateOfTheWrongSize) {
  DenseSystem sys = test::gyroscopic_oscillator();
  State s = test::initial_state(3);
  Newmark integ{IntegratorSettings{}};
  const StepReport r = integ.start(sys, s);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("3 displacements"), std::string::npos) << r.message;
}

// The trapezoidal rule conserves ½vᵀMv + ½xᵀKx exactly for a linear undamped system
// (the increments of kinetic and potential energy cancel). 10 000 steps of Δt = 0.5 s
// (ω·Δt up to 1.2, far from resolving the motion) leave only round-off: measured
// relative drift 3.7e-14; the bound 1e-12 leaves room for the accumulated round-off of
// other compilers and the Newton tolerance (1e-10 on corrections of a converged step
// that are themselves ~1e-16).
TEST(Newmark, TrapezoidalRuleConservesEnergyOfUndampedSystem) {
  DenseSystem sys = test::gyroscopic_oscillator();
  sys.D.setZero();
  sys.K = Matrix{{4.0, 0.7}, {0.7, 6.0}};  // symmetric: a conservative system
  sys.F.setZero();
  State s = test::initial_state(2);
  Newmark integ{IntegratorSettings{}};
  ASSERT_TRUE(integ.start(sys, s).ok);
  const auto energy = [&](const State& st) { return 0.5 * st.v.dot(sys.M * st.v) + 0.5 * st.x.dot(sys.K * st.x); };
  const Real e0 = energy(s);
  Real drift = 0.0;
  int factorizations = 0;
  for (int k = 0; k < 10000; ++k) {
    const StepReport r = integ.step(sys, s, 0.5);
    ASSERT_TRUE(r.ok) << r.message;
    // Linear: the first correction solves exactly, the second confirms it.
    EXPECT_EQ(r.iterations, 2);
    factorizations += r.factorizations;
    drift = std::max(drift, std::abs(energy(s) - e0) / e0);
  }
  EXPECT_LT(drift, 1e-12);
  // Constant Δt and a constant tangent: modified Newton keeps the first factorisation.
  EXPECT_EQ(factorizations, 1);
  EXPECT_NEAR(s.t, 5000.0, 1e-9);
}

// A linear system whose factorised Jacobian is exact: the first correction solves the
// step, so one iteration is taken, and the trajectory is the one that confirming
// every step with a second iteration gives. 2 000 steps of the forced, damped,
// gyroscopic oscillator at Δt = 0.01 s; the two differ by the second corrections,
// which are round-off (~1e-16 of ‖x‖ each): measured 4e-16; bound 1e-12 of the
// amplitude for other compilers' round-off.
TEST(Newmark, OneIterationWhenTheTangentIsExact) {
  DenseSystem confirmed = test::gyroscopic_oscillator();
  DenseSystem direct = test::gyroscopic_oscillator();
  direct.report_exact_tangent = true;
  State a = test::initial_state(2), b = test::initial_state(2);
  Newmark ia{IntegratorSettings{}}, ib{IntegratorSettings{}};
  ASSERT_TRUE(ia.start(confirmed, a).ok);
  ASSERT_TRUE(ib.start(direct, b).ok);
  Real difference = 0.0, amplitude = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const StepReport ra = ia.step(confirmed, a, 0.01);
    const StepReport rb = ib.step(direct, b, 0.01);
    ASSERT_TRUE(ra.ok && rb.ok);
    EXPECT_EQ(ra.iterations, 2);
    EXPECT_EQ(rb.iterations, 1);
    difference = std::max(difference, (a.x - b.x).norm());
    amplitude = std::max(amplitude, a.x.norm());
  }
  EXPECT_LT(difference, 1e-12 * amplitude);
  EXPECT_EQ(direct.n_factor, 1);
}

// Duffing oscillator x'' + x + 100x³ = 0 from x = 1: strongly nonlinear (the cubic
// force is 100 times the linear one).
DenseSystem duffing() {
  DenseSystem sys = test::undamped_sdof(1.0);
  sys.cubic = 100.0;
  return sys;
}

State duffing_start() {
  State s;
  s.x = Vector::Constant(1, 1.0);
  s.v = Vector::Zero(1);
  return s;
}

TEST(Newmark, NewtonIteratesOnANonlinearProblem) {
  DenseSystem sys = duffing();
  State s = duffing_start();
  Newmark integ{IntegratorSettings{}};
  ASSERT_TRUE(integ.start(sys, s).ok);
  int iterations = 0;
  for (int k = 0; k < 100; ++k) {
    const StepReport r = integ.step(sys, s, 0.01);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_GE(r.iterations, 2);  // nonlinear: one correction cannot be small enough
    iterations += r.iterations;
  }
  EXPECT_LT(iterations, 100 * 10);  // measured 381: modified Newton, 3.8 per step
  // Converged: M·a = r at the new state within what the Newton tolerance 1e-10 on x
  // allows (stiffness 1 + 300x² ≤ 301, times 1/(βΔt²) = 4e4 for a: ~1e-3 at most;
  // measured far smaller).
  Vector r;
  sys.rhs(s.t, s.x, s.v, r);
  EXPECT_LT((sys.M * s.a - r).norm(), 1e-3);
  // Energy ½v² + ½x² + 25x⁴ is conserved by the trapezoidal rule only for linear
  // systems; here it stays within a few percent over 100 steps (measured < 1 %).
  const Real e = 0.5 * s.v(0) * s.v(0) + 0.5 * s.x(0) * s.x(0) + 25.0 * std::pow(s.x(0), 4);
  EXPECT_NEAR(e, 25.5, 0.05 * 25.5);
}

TEST(Newmark, ReportsNewtonFailureWithItsIterationCount) {
  DenseSystem sys = duffing();
  State s = duffing_start();
  IntegratorSettings settings;
  settings.newton_max_iterations = 1;
  Newmark integ(settings);
  ASSERT_TRUE(integ.start(sys, s).ok);
  const State before = s;
  const StepReport r = integ.step(sys, s, 0.01);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_NE(r.message.find("did not converge in 1 iteration"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("last correction norm"), std::string::npos) << r.message;
  // The state is left as it was.
  EXPECT_EQ(s.t, before.t);
  EXPECT_EQ(s.x, before.x);
  EXPECT_EQ(s.v, before.v);
  EXPECT_EQ(s.a, before.a);
}

TEST(Newmark, RejectsBadSettings) {
  IntegratorSettings settings;
  EXPECT_THROW(Newmark(settings, NewmarkParameters{0.0, 0.5}), Error);
  settings.newton_max_iterations = 0;
  EXPECT_THROW(Newmark{settings}, Error);
  settings = IntegratorSettings{};
  settings.newton_tol = 0.0;
  EXPECT_THROW(Newmark{settings}, Error);
}

}  // namespace
}  // namespace feran
