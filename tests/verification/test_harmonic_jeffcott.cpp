// Jeffcott rotor under unbalance: a point mass m on an isotropic spring k with
// external damping c_a and internal (rotating) damping c_i. In complex form
// m r'' + (c_a + c_i) r' + (k − iΩc_i) r = m_u e Ω² e^{iΩt}; the synchronous response
// r = R e^{iΩt} has R = m_u e Ω² / (k − mΩ² + iΩc_a): the rotating damper sees no
// relative velocity on a synchronous circular orbit and drops out.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/response/harmonic_response.hpp>

#include "test_models.hpp"

namespace feran::test_harmonic_jeffcott {
namespace {

constexpr Real m = 9.1, k = 1.6e5, mu = 0.01, e = 0.08;

Model jeffcott(Real ca, Real ci, Real phase = 0.3) {
  Model model = test::jeffcott(m, k, ca, ci);
  model.forces.emplace_back(Unbalance{0, mu, e, phase, 0.0}, "u");
  return model;
}

void check_against_closed_form(Real ca, Real ci) {
  const Real wn = std::sqrt(k / m);
  HarmonicOptions opt;
  for (int i = 1; i <= 60; ++i) opt.speeds.push_back(wn * (0.05 * i + 0.013));  // across resonance, off-grid
  opt.probes = {0};
  const HarmonicResult r = run_harmonic_response(jeffcott(ca, ci), opt);
  ASSERT_TRUE(r.info.converged());
  for (std::size_t i = 0; i < opt.speeds.size(); ++i) {
    const Real W = opt.speeds[i];
    const Complex R = mu * e * W * W * std::polar(1.0, 0.3) / Complex(k - m * W * W, W * ca);
    const Orbit& o = r.probes[0].orbit[i];
    // Direct sparse LU of a 2×2 complex system: round-off only, 1e-10 relative.
    EXPECT_NEAR(o.major, std::abs(R), 1e-10 * std::abs(R)) << "Ω/ωn = " << W / wn;
    EXPECT_NEAR(o.minor, std::abs(R), 1e-10 * std::abs(R));  // circular
    EXPECT_EQ(o.whirl, Whirl::forward);
    const Complex v = r.probes[0].q[i][static_cast<std::size_t>(Dof::v)];
    EXPECT_NEAR(std::abs(v - R), 0.0, 1e-10 * std::abs(R)) << "amplitude and phase of v";
  }
}

TEST(HarmonicJeffcott, UndampedAcrossResonance) { check_against_closed_form(0.0, 0.0); }
TEST(HarmonicJeffcott, DampedAcrossResonance) { check_against_closed_form(250.0, 0.0); }
TEST(HarmonicJeffcott, RotatingDampingDoesNotChangeTheSynchronousOrbit) { check_against_closed_form(250.0, 638.0); }

TEST(HarmonicJeffcott, PhaseLagIsNinetyDegreesAtResonance) {
  const Real wn = std::sqrt(k / m);
  HarmonicOptions opt;
  opt.speeds = {wn};
  opt.probes = {0};
  const Model model = jeffcott(250.0, 0.0, 0.0);
  const HarmonicResult r = run_harmonic_response(model, opt);
  const Complex v = r.probes[0].q[0][static_cast<std::size_t>(Dof::v)];
  EXPECT_NEAR(std::arg(v), -pi / 2, 1e-12);  // response lags the unbalance by 90°
}

TEST(HarmonicJeffcott, SpringForceIsStiffnessTimesDisplacement) {
  const Real wn = std::sqrt(k / m);
  HarmonicOptions opt;
  opt.speeds = {0.7 * wn};
  opt.probes = {0};
  const HarmonicResult r = run_harmonic_response(jeffcott(250.0, 0.0), opt);
  const Complex v = r.probes[0].q[0][static_cast<std::size_t>(Dof::v)];
  const Complex fy = r.springs[0].force[0][static_cast<std::size_t>(Dof::v)];
  const Complex expected = (k + Complex(0, 0.7 * wn * 250.0)) * v;
  EXPECT_NEAR(std::abs(fy - expected), 0.0, 1e-10 * std::abs(expected));
  EXPECT_NEAR(r.springs[0].peak_lateral[0], std::abs(expected), 1e-10 * std::abs(expected));
}

// Hysteretic damping: a loss factor η on the spring, or a global one, turns k into
// k(1 + iη): R = m_u e Ω² e^{iφ}/(k(1 + iη) − mΩ²).
TEST(HarmonicJeffcott, LossFactorMakesTheStiffnessComplex) {
  const Real wn = std::sqrt(k / m), eta = 0.04;
  for (bool global : {false, true}) {
    Model model = jeffcott(0.0, 0.0);
    HarmonicOptions opt;
    if (global) {
      opt.loss_factor = eta;
    } else {
      SpringDamperCoefficients c = model.elements[1].target<SpringDamper>()->coefficients();
      c.loss_factor = eta;
      model.elements[1] = SpringDamper(0, std::nullopt, c);
    }
    opt.speeds = {0.5 * wn, wn, 1.7 * wn};
    opt.probes = {0};
    const HarmonicResult r = run_harmonic_response(model, opt);
    for (std::size_t i = 0; i < opt.speeds.size(); ++i) {
      const Real W = opt.speeds[i];
      const Complex R = mu * e * W * W * std::polar(1.0, 0.3) / (Complex(k, k * eta) - m * W * W);
      const Complex v = r.probes[0].q[i][static_cast<std::size_t>(Dof::v)];
      EXPECT_NEAR(std::abs(v - R), 0.0, 1e-10 * std::abs(R)) << (global ? "global" : "element");
    }
  }
}

}  // namespace
}  // namespace feran::test_harmonic_jeffcott
