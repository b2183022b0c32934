// Jeffcott rotor: a point mass m on an isotropic spring k, with external damping
// c_a (non-rotating) and internal damping c_i (rotating). Closed forms:
//   critical speed ω_n = √(k/m);
//   at rest, damping ratio (c_a + c_i)/(2√(km));
//   unstable above Ω = ω_n·(1 + c_a/c_i) (in complex form m r'' + (c_a + c_i) r' +
//   (k − iΩc_i) r = 0 has a root on the imaginary axis exactly there).
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/modal/modal.hpp>

#include "test_models.hpp"

namespace feran::test_jeffcott {
namespace {

constexpr Real m = 9.1, k = 1.6e5, c_a = 250.0, c_i = 638.0;

Model jeffcott(Real ca, Real ci) { return test::jeffcott(m, k, ca, ci); }

std::vector<Real> linspace(Real a, Real b, int n) {
  std::vector<Real> v;
  for (int i = 0; i < n; ++i) v.push_back(a + (b - a) * i / (n - 1));
  return v;
}

TEST(Jeffcott, NaturalFrequencyAndDampingAtRest) {
  const ModalResult r = run_modal(jeffcott(c_a, c_i), 0.0);
  ASSERT_EQ(r.modes.size(), 2u);
  const Real wn = std::sqrt(k / m), zeta = (c_a + c_i) / (2 * std::sqrt(k * m));
  for (const Mode& mode : r.modes) {
    // Damped frequency ω_n√(1 − ζ²); 1e-10 relative: a 4×4 dense eigenproblem is
    // accurate to round-off (~1e-14) times a modest condition number.
    EXPECT_NEAR(mode.frequency_hz, rad_to_hz(wn * std::sqrt(1 - zeta * zeta)), 1e-10 * rad_to_hz(wn));
    EXPECT_NEAR(mode.damping_ratio, zeta, 1e-10);
    EXPECT_NEAR(mode.log_decrement, 2 * pi * zeta / std::sqrt(1 - zeta * zeta), 1e-9);
  }
  // The repeated pair is split into one forward and one backward circle.
  EXPECT_NE(r.modes[0].whirl, r.modes[1].whirl);
  EXPECT_NEAR(std::abs(r.modes[0].directivity), 1.0, 1e-9);
}

TEST(Jeffcott, CriticalSpeedIsSqrtKOverM) {
  CampbellOptions opt;
  opt.speeds = linspace(0.0, 2.0 * std::sqrt(k / m), 21);
  opt.n_modes = 2;
  const CampbellResult r = run_campbell(jeffcott(0.0, 0.0), opt);
  ASSERT_EQ(r.modes.size(), 2u);
  // Undamped, no gyroscopic effect: both whirls cross the 1× line at ω_n.
  ASSERT_EQ(r.critical_speeds.size(), 2u);
  for (const CriticalSpeed& cs : r.critical_speeds)
    EXPECT_NEAR(cs.speed, std::sqrt(k / m), 1e-8 * std::sqrt(k / m));  // Brent tolerance 1e-8 rad/s
  EXPECT_FALSE(r.stability_threshold.has_value());
}

TEST(Jeffcott, InternalDampingThreshold) {
  const Real wn = std::sqrt(k / m);
  CampbellOptions opt;
  opt.speeds = linspace(0.0, 2.0 * wn, 41);
  opt.n_modes = 2;
  const CampbellResult r = run_campbell(jeffcott(c_a, c_i), opt);
  ASSERT_TRUE(r.stability_threshold.has_value());
  // Brent refines to 1e-8 rad/s, the root of the damping ratio is simple: 1e-7 relative.
  EXPECT_NEAR(r.stability_threshold->speed, wn * (1 + c_a / c_i), 1e-7 * wn);
  EXPECT_EQ(r.modes[static_cast<std::size_t>(r.stability_threshold->mode)].whirl, Whirl::forward);
  EXPECT_FALSE(r.stability_threshold->unstable_at_start);
}

TEST(Jeffcott, ExternalDampingAloneStaysStable) {
  CampbellOptions opt;
  opt.speeds = linspace(0.0, 5.0 * std::sqrt(k / m), 11);
  opt.n_modes = 2;
  EXPECT_FALSE(run_campbell(jeffcott(c_a, 0.0), opt).stability_threshold.has_value());
}

}  // namespace
}  // namespace feran::test_jeffcott
