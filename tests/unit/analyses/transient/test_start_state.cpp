// Where a run-up starts: at the static equilibrium under gravity, or in the steady
// unbalance response at its first speed, so that a run at constant speed shows no
// start-up transient.

#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/elements/rigid_body.hpp>
#include <feran/elements/spring_damper.hpp>
#include <feran/forces/harmonic_force.hpp>
#include <feran/forces/unbalance.hpp>

namespace feran::test_start_state {
namespace {

// A disk of mass m on an anisotropic damped support (k_y ≠ k_z) with an unbalance:
// x(t) = Re(X e^{iΩt}) per direction, X = m_u r Ω² / (k − mΩ² + icΩ) (times −i for z).
constexpr Real mass = 10.0, ky = 4e6, kz = 6e6, cy = 800.0, cz = 1200.0, mu = 1e-3, radius = 0.05;

Model disk_on_support() {
  Model model;
  model.nodes = {{1, "disk", 0.0, true}};
  model.elements.emplace_back(
      RigidBody(0, {.mass = mass, .transverse_inertia = 0.1, .polar_inertia = 0.2, .offset = 0.0}, true), "disk");
  SpringDamperCoefficients c;
  c.k[static_cast<std::size_t>(Dof::v)] = ky;
  c.k[static_cast<std::size_t>(Dof::w)] = kz;
  c.c[static_cast<std::size_t>(Dof::v)] = cy;
  c.c[static_cast<std::size_t>(Dof::w)] = cz;
  model.elements.emplace_back(SpringDamper(0, std::nullopt, c), "support");
  FixedDofs fixed{.node = 0, .dofs = {}};
  for (const Dof d : {Dof::u, Dof::rx, Dof::ry, Dof::rz}) fixed.dofs[static_cast<std::size_t>(d)] = true;
  model.fixed.push_back(fixed);
  model.forces.emplace_back(Unbalance{.node = 0, .mass = mu, .radius = radius, .phase = 0.0, .lever = 0.0}, "u");
  model.gravity = Eigen::Vector3d(0, -9.81, 0);
  return model;
}

TransientOptions constant_run(Real speed, RunupStart start) {
  TransientOptions options;
  options.profile = SpeedProfile::constant(speed);
  options.duration = 0.05;
  options.integrator = "trapezoidal";
  options.settings.dt = 1e-6;
  options.output_interval = 1e-4;
  options.probes = {0};
  options.gravity = Eigen::Vector3d(0, -9.81, 0);
  options.start = start;
  return options;
}

TEST(StartState, SteadyStartFollowsTheClosedFormOrbitFromTheFirstStep) {
  // From the steady state the motion is the closed-form orbit about the static sag
  // −mg/k_y at every sample, with no start-up transient (which from rest would be of
  // the orbit's size, decaying at ζω ≈ 40 1/s, i.e. still 14 % after 50 ms).
  // Tolerance 1e-6 of the orbit: the trapezoidal rule's phase error (Ω·dt)²·Ω·t/12 ≈
  // 3e-7 rad at 300 rad/s after 50 ms, with dt = 1 µs.
  const Real speed = 300.0;
  const Model model = disk_on_support();
  const TransientResult r = run_transient(model, constant_run(speed, RunupStart::steady_state));
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  const Complex F = mu * radius * speed * speed;
  const Complex Y = F / Complex(ky - mass * speed * speed, cy * speed);
  const Complex Z = Complex(0, -1) * F / Complex(kz - mass * speed * speed, cz * speed);
  const Real sag = -mass * 9.81 / ky;
  Real worst = 0.0;
  for (const TransientSample& s : r.samples) {
    const Complex e = std::exp(Complex(0, speed * s.t));
    worst = std::max(worst, std::abs(s.probes[0][1] - sag - (Y * e).real()));
    worst = std::max(worst, std::abs(s.probes[0][2] - (Z * e).real()));
  }
  EXPECT_LT(worst, 1e-6 * std::abs(Y));
  // From rest the same run starts far from that orbit.
  const TransientResult rest = run_transient(model, constant_run(speed, RunupStart::rest));
  EXPECT_GT(
      std::abs(rest.samples[10].probes[0][1] - sag - (Y * std::exp(Complex(0, speed * rest.samples[10].t))).real()),
      0.1 * std::abs(Y));
}

TEST(StartState, EquilibriumStartHoldsTheStaticSag) {
  // Without the unbalance, a run started at the equilibrium stays at −mg/k_y (to
  // round-off: the state is a fixed point of every step).
  Model model = disk_on_support();
  model.forces.clear();
  const TransientResult r = run_transient(model, constant_run(100.0, RunupStart::equilibrium));
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  const Real sag = -mass * 9.81 / ky;
  for (const TransientSample& s : r.samples) {
    EXPECT_NEAR(s.probes[0][1], sag, 1e-12 * std::abs(sag));
    EXPECT_NEAR(s.probes[0][2], 0.0, 1e-12 * std::abs(sag));
  }
}

TEST(StartState, ForceAtItsOwnFrequencyDrivesTheRunAtThatFrequency) {
  // A fixed force A·cos(ωt) along y at ω = 450 rad/s on the disk turning at 300 rad/s
  // (no unbalance, no gravity): once the start-up transient has decayed (ζω ≈ 40 1/s;
  // after 0.35 s e^{-14}), the motion is Re(A/(k_y − mω² + icω)·e^{iωt}) to 1e-6 of it.
  Model model = disk_on_support();
  model.forces.clear();
  constexpr Real A = 100.0, omega = 450.0;
  model.forces.emplace_back(HarmonicForce{.node = 0,
                                          .type = HarmonicForce::Kind::fixed,
                                          .direction = Dof::v,
                                          .amplitude = A,
                                          .phase = 0.0,
                                          .frequency = omega,
                                          .time_table = {}},
                            "shaker");
  TransientOptions options = constant_run(300.0, RunupStart::rest);
  options.gravity.setZero();
  options.duration = 0.4;
  const TransientResult r = run_transient(model, options);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  const Complex Y = A / Complex(ky - mass * omega * omega, cy * omega);
  Real worst = 0.0;
  for (const TransientSample& s : r.samples)
    if (s.t >= 0.35) worst = std::max(worst, std::abs(s.probes[0][1] - (Y * std::exp(Complex(0, omega * s.t))).real()));
  EXPECT_LT(worst, 1e-6 * std::abs(Y));
}

TEST(StartState, ForceGivenInTimeFollowsTheClosedFormRampResponse) {
  // A fixed force along y given as a time table: a ramp from 0 to F0 over t1, then
  // held. For t ≤ t1, m y'' + c y' + k y = a t (a = F0/t1) from rest has
  // y = (a/k)(t − c/k) + e^{−ζω_n t}(A cos ω_d t + B sin ω_d t), A = ac/k²,
  // B = (ζω_n A − a/k)/ω_d; after the transient (ζω_n = 40 1/s, 0.4 s: e^{−15}) the
  // disk rests at F0/k. Tolerance 1e-6 of F0/k: the trapezoidal rule's error with
  // dt = 1 µs (frequency 100 Hz) is ~1e-9 of it.
  Model model = disk_on_support();
  model.forces.clear();
  constexpr Real F0 = 500.0, t1 = 0.02;
  HarmonicForce push;
  push.node = 0;
  push.type = HarmonicForce::Kind::fixed;
  push.direction = Dof::v;
  push.time_table = {{0.0, 0.0}, {t1, F0}};
  model.forces.emplace_back(push, "push");
  TransientOptions options = constant_run(300.0, RunupStart::rest);
  options.gravity.setZero();
  options.duration = 0.4;
  const TransientResult r = run_transient(model, options);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  const Real a = F0 / t1, wn = std::sqrt(ky / mass), zeta = cy / (2 * std::sqrt(ky * mass));
  const Real wd = wn * std::sqrt(1 - zeta * zeta);
  const Real A = a * cy / (ky * ky), B = (zeta * wn * A - a / ky) / wd;
  Real worst_ramp = 0.0, worst_end = 0.0, largest = 0.0;
  for (const TransientSample& s : r.samples) {
    largest = std::max(largest, std::abs(s.probes[0][1]));
    if (s.t <= t1) {
      const Real y =
          a / ky * (s.t - cy / ky) + std::exp(-zeta * wn * s.t) * (A * std::cos(wd * s.t) + B * std::sin(wd * s.t));
      worst_ramp = std::max(worst_ramp, std::abs(s.probes[0][1] - y));
    } else if (s.t >= 0.38) {
      worst_end = std::max(worst_end, std::abs(s.probes[0][1] - F0 / ky));
    }
  }
  EXPECT_LT(worst_ramp, 1e-6 * F0 / ky);
  EXPECT_LT(worst_end, 1e-6 * F0 / ky);
  EXPECT_GT(largest, 0.9 * F0 / ky);  // it did move
  // The force takes no part in the steady-state (harmonic) load.
  ComplexVector f = ComplexVector::Zero(6);
  push.add_harmonic({}, f);
  EXPECT_EQ(f.norm(), 0.0);
}

}  // namespace
}  // namespace feran::test_start_state
