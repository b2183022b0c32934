// A run at constant speed until the motion settles, and the orbit it settled on
// (analyses/periodic/settle.hpp), as the start of a branch (branch_through):
// - the rigid rotor of Friswell et al. (2010), Example 5.5.1, in two short bearings
//   carrying 525 N each, at 950 rad/s (above its threshold, 863.345 rad/s, where the
//   equilibrium is unstable): the run grows into the whip, and the orbit it settles on,
//   corrected by the balance, is the whirl branch's orbit there (the branch leaving the
//   Hopf point, 1e-8: the balance's tolerance); the run's own orbit, before the
//   correction, within 1 % in frequency and 2 % in its first harmonic (BDF2 at 64
//   steps a revolution: its phase error (ωΔt)²/12 and its damping; measured 8e-4 and
//   5e-3). Followed down it turns at the whirl branch's fold (1e-5, as the given-orbit
//   test) and ends where it meets the equilibrium, at the Hopf point (its last orbit a
//   small unstable one between the fold and the Hopf point). At 850 rad/s (between the branch's fold and the threshold:
//   the equilibrium stable and the run's start inside its region of attraction) it dies out, and says so;
// - Duffing's oscillator at Ω = 1.5 between its two folds (1.2084 and 1.7322), where
//   the small and the large orbits are both stable: the run from near rest settles on
//   the small one (the smallest root of the single-harmonic response, 1e-8 after the
//   correction), and the branch through it going down meets the fold where the small
//   orbits end (the closed form's, 1e-6 as the forced branch's own test).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <feran/analyses/periodic/settle.hpp>
#include <feran/core/error.hpp>

#include "duffing.hpp"
#include "test_models.hpp"

namespace feran::test_settle {
namespace {

Real first_harmonic(const Vector& X, Index n) { return X.segment(n, 2 * n).norm(); }

TEST(Settle, ARunAboveTheThresholdSettlesOnTheWhipAndItsBranchIsTheWhirlBranch) {
  const Model model = test::rigid_rotor_in_journal_bearings(525.0 / 9.81, FilmTheory::short_bearing);
  const CondensedRotor rotor(
      model, nullptr,
      {.modes = 12, .gravity = model.gravity, .static_loads = true, .unbalance = false, .reference_speed = 500.0});
  const Index n = rotor.size();
  OrbitSettings settings;
  settings.continuation.p_min = 600.0;
  settings.continuation.p_max = 1100.0;
  const OrbitBranch eq = equilibrium_branch(rotor, settings);
  ASSERT_FALSE(eq.bifurcations.empty());
  settings.fourier = {.harmonics = 8, .samples = 64};
  settings.continuation.max_points = 60;
  const OrbitBranch whirl = hopf_branch(rotor, eq.bifurcations[0], settings);
  const std::vector<SteadyState> at = states_at(rotor, whirl, 950.0, settings);
  ASSERT_EQ(at.size(), 1U);
  ASSERT_TRUE(at[0].stable);

  const RotorFamily family(rotor);
  const SettledOrbit run = settle_orbit(family, 950.0, settings);
  EXPECT_EQ(run.kind, OrbitBranch::Kind::self_excited);
  EXPECT_LT(run.mismatch, 1e-3);
  EXPECT_NEAR(run.start.frequency, at[0].frequency, 1e-2 * at[0].frequency);
  EXPECT_NEAR(first_harmonic(run.start.X, n), first_harmonic(at[0].X, n), 2e-2 * first_harmonic(at[0].X, n));
  OrbitSettings short_branch = settings;
  short_branch.continuation.max_points = 3;
  const OrbitBranch through = branch_through(family, run.start, run.kind, short_branch);
  ASSERT_FALSE(through.orbits.empty());
  const SteadyState& o = through.orbits.front();
  EXPECT_EQ(o.parameter, 950.0);
  EXPECT_NEAR(o.frequency, at[0].frequency, 1e-8 * at[0].frequency);
  EXPECT_NEAR(first_harmonic(o.X, n), first_harmonic(at[0].X, n), 1e-8 * first_harmonic(at[0].X, n));
  EXPECT_TRUE(o.stable);
  // Followed down, the branch through it turns at the whirl branch's fold and comes
  // back to the equilibrium at the Hopf point, where it ends (rather than going on
  // through it as the same orbits half a period later).
  OrbitSettings longer = settings;
  longer.continuation.max_points = 200;
  const OrbitBranch down = branch_through(family, run.start, run.kind, longer, true);
  ASSERT_FALSE(down.bifurcations.empty()) << down.ended_by;
  EXPECT_EQ(down.bifurcations[0].kind, Bifurcation::Kind::fold);
  EXPECT_NEAR(down.bifurcations[0].at.speed, whirl.bifurcations.at(0).at.speed, 1e-5 * whirl.bifurcations[0].at.speed);
  EXPECT_EQ(down.bifurcations.size(), 1U);
  EXPECT_NE(down.ended_by.find("meets the static equilibrium"), std::string::npos) << down.ended_by;
  // Its last state: a small unstable orbit between the fold and the Hopf point.
  EXPECT_GT(down.orbits.back().speed, down.bifurcations[0].at.speed);
  EXPECT_LT(down.orbits.back().speed, eq.bifurcations[0].at.speed);
  EXPECT_FALSE(down.orbits.back().stable);

  try {
    (void)settle_orbit(family, 850.0, settings);
    ADD_FAILURE() << "a run that dies out settled on an orbit";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("dies out onto the static equilibrium"), std::string::npos) << e.what();
  }
}

TEST(Settle, ARunOfTheForcedDuffingRotorBetweenItsFoldsSettlesOnTheSmallOrbit) {
  using namespace test::duffing;  // NOLINT(google-build-using-namespace): the shared case's names
  const Model model = rotor_model();
  const CondensedRotor rotor = condense(model);
  const OrbitSettings settings = branch_settings();
  const std::vector<Real> amplitudes = orbit_amplitudes(1.5), folds = closed_form_folds();
  ASSERT_EQ(amplitudes.size(), 3U);
  ASSERT_EQ(folds.size(), 2U);

  const RotorFamily family(rotor);
  const SettledOrbit run = settle_orbit(family, 1.5, settings);
  EXPECT_EQ(run.kind, OrbitBranch::Kind::forced);
  EXPECT_EQ(run.start.frequency, 1.5);
  const OrbitBranch down = branch_through(family, run.start, run.kind, settings, true);
  ASSERT_FALSE(down.orbits.empty());
  EXPECT_NEAR(std::hypot(down.orbits[0].X(1), down.orbits[0].X(2)), amplitudes[0], 1e-8);
  EXPECT_TRUE(down.orbits[0].stable);
  ASSERT_FALSE(down.bifurcations.empty()) << down.ended_by;
  EXPECT_EQ(down.bifurcations[0].kind, Bifurcation::Kind::fold);
  EXPECT_NEAR(down.bifurcations[0].at.speed, folds[0], 1e-6);
}

}  // namespace
}  // namespace feran::test_settle
