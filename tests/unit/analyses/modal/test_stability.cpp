// The rotor's stability at a speed (analyses/modal/stability.hpp), against the closed
// form of the Jeffcott rotor: in complex coordinates z = v + i·w,
//   m z'' + (c_a + c_i) z' + (k − iΩ c_i) z = 0,
// whose eigenvalues p = [−(c_a + c_i) ± √((c_a + c_i)² − 4m(k − iΩ c_i))]/(2m) (and
// their conjugates, for the backward whirl) give the growth rate max Re p exactly;
// the forward mode turns unstable at Ω = ω_n(1 + c_a/c_i). A negative stiffness
// diverges at the real rate (−c + √(c² + 4m|k|))/(2m).
#include <cmath>
#include <complex>
#include <vector>

#include <gtest/gtest.h>

#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/analyses/modal/stability.hpp>
#include <feran/analyses/static/equilibrium.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/io/model_reader.hpp>

#include "test_models.hpp"

namespace feran::test_stability {
namespace {

constexpr Real m = 9.1, k = 1.6e5, ca = 50, ci = 100;

Real closed_form_growth(Real speed) {
  Real best = -1e300;
  for (const Real sign : {1.0, -1.0}) {  // forward (k − iΩc_i) and backward (k + iΩc_i)
    const std::complex<Real> root =
        std::sqrt(std::complex<Real>((ca + ci) * (ca + ci), 0) - 4 * m * std::complex<Real>(k, -sign * speed * ci));
    for (const Real branch : {1.0, -1.0}) best = std::max(best, ((-(ca + ci) + branch * root) / (2 * m)).real());
  }
  return best;
}

TEST(Stability, JeffcottWithRotatingDampingMatchesTheClosedFormEitherSideOfItsThreshold) {
  const Model model = test::jeffcott(m, k, ca, ci);
  const Real threshold = std::sqrt(k / m) * (1 + ca / ci);
  for (const Real ratio : {0.0, 0.5, 0.95, 1.05, 2.0}) {
    const Real speed = ratio * threshold;
    const StabilityPoint p = stability_at(model, speed);
    ASSERT_TRUE(p.known) << p.message;
    EXPECT_EQ(p.unstable, ratio > 1) << "at " << ratio << " x the threshold";
    EXPECT_FALSE(p.divergence);
    if (ratio > 0) {
      // The circulatory Ω·K_i leaves the energy test; the eigenvalues decide (their
      // relative accuracy, ~1e-12 of |p| = 132 1/s).
      EXPECT_FALSE(p.by_energy);
      EXPECT_NEAR(p.growth_rate, closed_form_growth(speed), 1e-9 * std::sqrt(k / m)) << "at " << ratio;
    }
  }
}

TEST(Stability, AConservativeRotorIsStableByTheEnergyTestAndTheEigenvaluesAgree) {
  const Model model = test::friswell_5_9_1();
  const StabilityPoint p = stability_at(model, 2000.0);
  EXPECT_TRUE(p.known && p.by_energy && !p.unstable);
  // Damped: every eigenvalue's real part ≤ 0 in the modal analysis too.
  const Model damped = test::jeffcott(m, k, ca, 0.0);
  const StabilityPoint q = stability_at(damped, 300.0);
  EXPECT_TRUE(q.by_energy && !q.unstable);
}

TEST(Stability, APassivePedestalGivenByFrequencyTablesIsStableAndTheEigenvaluesAgree) {
  // Example 07: the pedestal condensed into tables over frequency (symmetric, damping
  // positive at every frequency): passive, so stable without eigenvalues; the modal
  // analysis, each mode at its own frequency, finds no growing mode either.
  const ModelFile file = read_model_file(FERAN_SOURCE_DIR "/examples/07_pedestal/model.toml");
  for (const Real speed : {100.0, 314.0}) {
    const StabilityPoint p = stability_at(file.model, speed);
    EXPECT_TRUE(p.known && p.by_energy && !p.unstable) << speed;
    ModalOptions options;
    options.shapes = false;
    options.n_modes = 12;
    const ModalResult r = run_modal(file.model, speed, options);
    ASSERT_TRUE(r.info.converged()) << r.info.message;
    for (const Mode& mode : r.modes) {
      if (mode.rigid_body) continue;
      EXPECT_LE(mode.eigenvalue.real(), 1e-9 * std::abs(mode.eigenvalue)) << speed;
    }
  }
}

TEST(Stability, ANegativeStiffnessDivergesAtItsRealRateNotAsARigidBodyMode) {
  const Real kn = -2e4, c = 30;
  Model model = test::jeffcott(m, kn, c, 0.0);
  const StabilityPoint p = stability_at(model, 100.0);
  ASSERT_TRUE(p.known) << p.message;
  EXPECT_TRUE(p.unstable);
  EXPECT_TRUE(p.divergence);
  EXPECT_EQ(p.frequency_hz, 0.0);
  EXPECT_NEAR(p.growth_rate, (-c + std::sqrt(c * c + 4 * m * -kn)) / (2 * m), 1e-9 * std::sqrt(-kn / m));
}

// A Jeffcott rotor whose spring softens with speed, k(Ω) = k0·(1 − Ω/Ω_d) (a table
// linear in speed), diverges from Ω_d on, where k turns negative: a real eigenvalue
// is born at p = 0 and no oscillating mode shows it.
Model softening_jeffcott(Real k0, Real divergence_speed, Real c) {
  Model model = test::jeffcott(m, 1.0, c, 0.0);
  SpringDamperCoefficients sc;
  const SpeedCoefficient law(SpeedCoefficient::Table{{0.0, 2 * divergence_speed}, {k0, -k0}});
  sc.k[static_cast<std::size_t>(Dof::v)] = law;
  sc.k[static_cast<std::size_t>(Dof::w)] = law;
  sc.c[static_cast<std::size_t>(Dof::v)] = c;
  sc.c[static_cast<std::size_t>(Dof::w)] = c;
  model.elements.back() = Element(SpringDamper(0, std::nullopt, sc));
  return model;
}

TEST(Stability, TheCampbellThresholdFindsADivergenceThatNoTrackedModeShows) {
  // The onset is where k(Ω) = 0, Ω_d = 100 rad/s; bisected to the sweep's speed
  // tolerance, it lies above Ω_d by no more than that, plus the speed at which the
  // real eigenvalue −k(Ω)/c first exceeds round-off (1e-9 of the largest |p|):
  // asserted to 1e-6 relative.
  const Real divergence_speed = 100.0;
  const Model model = softening_jeffcott(k, divergence_speed, ca);
  CampbellOptions options;
  for (int i = 0; i <= 10; ++i) options.speeds.push_back(20.0 * i);
  options.n_modes = 2;
  const CampbellResult r = run_campbell(model, options);
  ASSERT_TRUE(r.info.converged()) << r.info.message;
  ASSERT_TRUE(r.stability_threshold);
  EXPECT_TRUE(r.stability_threshold->divergence);
  EXPECT_FALSE(r.stability_threshold->unstable_at_start);
  EXPECT_EQ(r.stability_threshold->mode, -1);
  EXPECT_NEAR(r.stability_threshold->speed / divergence_speed, 1.0, 1e-6);
  EXPECT_EQ(threshold_label(r, *r.stability_threshold), "divergence (a real eigenvalue)");
}

TEST(Stability, AStaticEquilibriumPastTheDivergenceIsFlaggedWithItsRate) {
  // At 1.5 Ω_d, k = −k0/2: m p² + c p + k = 0 has the real root
  // (−c + √(c² + 2 m k0))/(2m). Below Ω_d the same equilibrium is stable.
  const Real divergence_speed = 100.0;
  const Model model = softening_jeffcott(k, divergence_speed, ca);
  StaticOptions options;
  options.speed = 1.5 * divergence_speed;
  const StaticResult above = run_static(model, options);
  ASSERT_TRUE(above.stability.known) << above.stability.message;
  EXPECT_TRUE(above.stability.unstable);
  EXPECT_TRUE(above.stability.divergence);
  EXPECT_EQ(stability_kind(above.stability), "divergence");
  EXPECT_NEAR(above.stability.growth_rate, (-ca + std::sqrt(ca * ca + 2 * m * k)) / (2 * m), 1e-9 * std::sqrt(k / m));
  options.speed = 0.5 * divergence_speed;
  const StaticResult below = run_static(model, options);
  EXPECT_TRUE(below.stability.known);
  EXPECT_FALSE(below.stability.unstable);
  options.stability = false;
  EXPECT_FALSE(run_static(model, options).stability.known);
}

// A scan (what no speed changes judged once, one modal solver) gives at each speed
// what the point alone gives: the same computation, so the same numbers.
void expect_scan_as_each_point(const Model& model, const std::vector<Real>& speeds) {
  const Model linear = linearised(model);
  const StabilityScan scan(linear, needs_speed(model));
  for (const Real speed : speeds) {
    const StabilityPoint alone = stability_at(model, speed), scanned = scan.at(speed);
    EXPECT_EQ(scanned.known, alone.known) << speed << ": " << scanned.message << " / " << alone.message;
    EXPECT_EQ(scanned.message, alone.message) << speed;
    EXPECT_EQ(scanned.unstable, alone.unstable) << speed;
    EXPECT_EQ(scanned.by_energy, alone.by_energy) << speed;
    EXPECT_EQ(scanned.divergence, alone.divergence) << speed;
    if (!std::isnan(alone.growth_rate))
      EXPECT_NEAR(scanned.growth_rate, alone.growth_rate, 1e-12 * std::max(1.0, std::abs(alone.growth_rate))) << speed;
    else
      EXPECT_TRUE(std::isnan(scanned.growth_rate)) << speed;
    EXPECT_NEAR(scanned.frequency_hz, alone.frequency_hz, 1e-12 * std::max(1.0, alone.frequency_hz)) << speed;
  }
}

TEST(Stability, AScanGivesAtEachSpeedWhatThePointAloneGives) {
  // Rotating damping through its threshold (eigenvalues; circulatory above rest).
  const Real threshold = std::sqrt(k / m) * (1 + ca / ci);
  expect_scan_as_each_point(test::jeffcott(m, k, ca, ci), {0.0, 0.5 * threshold, 0.95 * threshold, 1.05 * threshold});
  // Conservative (the energy test alone).
  expect_scan_as_each_point(test::friswell_5_9_1(), {0.0, 500.0, 2000.0});
  // A spring table over speed, through its divergence (a varying element).
  expect_scan_as_each_point(softening_jeffcott(k, 100.0, ca), {50.0, 99.0, 150.0});
  // Frequency tables (a varying element, passive).
  expect_scan_as_each_point(read_model_file(FERAN_SOURCE_DIR "/examples/07_pedestal/model.toml").model, {100.0, 314.0});
  // Oil films: linearised about their equilibrium at each speed; at rest unknown.
  expect_scan_as_each_point(read_model_file(FERAN_SOURCE_DIR "/examples/06_oil_whip/model.toml").model,
                            {0.0, 300.0, 900.0});
}

}  // namespace
}  // namespace feran::test_stability
