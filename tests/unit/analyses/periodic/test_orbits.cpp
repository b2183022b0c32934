// Steady states of a condensed rotor (analyses/periodic/orbits.hpp) on the rigid
// rotor of Friswell et al. (2010), Example 5.5.1, in two short bearings carrying 525 N
// each:
// - the equilibrium branch's Hopf point is the linear stability threshold, 863.345
//   rad/s by the modal analysis' bisection (test_supports.cpp): to 1e-6 relative (the
//   location's tolerance on the arclength and the central difference in speed), with
//   a whirl ratio ω/Ω near one half;
// - the condensation of a rigid rotor keeps every DOF: its equilibrium at a speed is
//   solve_equilibrium's (to 1e-9 of the clearance);
// - the self-excited branch leaving the Hopf point (8 harmonics) is subcritical: its
//   small orbits lie below the threshold and are unstable (a real multiplier above 1),
//   it turns at a fold — the whip's jump-down speed — and comes back as large stable
//   orbits (whirl ratio ½, the journal near the clearance) above the threshold. The
//   fold converges as harmonics are added (H = 3, 6, 8, 10, 16: 801.52, 806.86,
//   807.19, 807.40, 807.55 rad/s); asserted within 0.5 % of 807.55. Every orbit solves
//   the balance to 1e-9;
// - a branch through a given orbit (one of that branch, spoilt) is that branch, and in
//   the oil's viscosity reaches the orbit of the rotor built with another viscosity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <feran/analyses/periodic/orbits.hpp>
#include <feran/analyses/static/equilibrium.hpp>

#include <feran/forces/harmonic_force.hpp>

#include "duffing.hpp"
#include "test_models.hpp"

namespace feran::test_orbits {
namespace {

constexpr JournalBearingGeometry friswell = test::friswell_5_5_1_bearing;
constexpr Real g = 9.81;

Model rigid_rotor(Real m_per_bearing) {
  return test::rigid_rotor_in_journal_bearings(m_per_bearing, FilmTheory::short_bearing);
}

constexpr Real threshold = 863.345;  // rad/s

CondensedRotor condensed(const Model& model) {
  return CondensedRotor(
      model, nullptr,
      {.modes = 12, .gravity = model.gravity, .static_loads = true, .unbalance = false, .reference_speed = 500.0});
}

TEST(Orbits, EquilibriumOfTheCondensedRigidRotorIsTheStaticOne) {
  const Model model = rigid_rotor(525.0 / g);
  const CondensedRotor rotor = condensed(model);
  EXPECT_EQ(rotor.size(), 4);  // v, w, ry, rz of the centre: nothing condensed away
  OrbitSettings settings;
  settings.continuation.p_min = 600.0;
  settings.continuation.p_max = 600.0 + 1e-9;
  settings.continuation.max_points = 2;
  const OrbitBranch b = equilibrium_branch(rotor, settings);
  ASSERT_FALSE(b.orbits.empty());
  const Vector q = rotor.expand(b.orbits.front().X);
  const Vector expected = solve_equilibrium(model, rotor.assembler(), 600.0, {.gravity = model.gravity}).q;
  EXPECT_LT((q - expected).cwiseAbs().maxCoeff(), 1e-9 * friswell.clearance);
}

TEST(Orbits, HopfPointIsTheLinearThresholdAndItsBranchLeavesIt) {
  const Model model = rigid_rotor(525.0 / g);
  const CondensedRotor rotor = condensed(model);
  OrbitSettings settings;
  settings.continuation.p_min = 600.0;
  settings.continuation.p_max = 1100.0;
  const OrbitBranch eq = equilibrium_branch(rotor, settings);
  EXPECT_TRUE(eq.clipped) << eq.ended_by;
  ASSERT_EQ(eq.bifurcations.size(), 1U);
  const Bifurcation& hopf = eq.bifurcations.front();
  EXPECT_EQ(hopf.kind, Bifurcation::Kind::hopf);
  EXPECT_NEAR(hopf.at.speed, threshold, 1e-6 * threshold);
  EXPECT_TRUE(eq.orbits.front().stable);
  EXPECT_FALSE(eq.orbits.back().stable);

  settings.fourier = {.harmonics = 8, .samples = 64};
  settings.continuation.max_points = 60;
  const OrbitBranch whirl = hopf_branch(rotor, hopf, settings);
  ASSERT_GT(whirl.orbits.size(), 5U) << whirl.ended_by;
  EXPECT_TRUE(whirl.clipped) << whirl.ended_by;
  EXPECT_EQ(whirl.criticality, "subcritical");
  ASSERT_EQ(whirl.bifurcations.size(), 1U);
  const Bifurcation& fold = whirl.bifurcations.front();
  EXPECT_EQ(fold.kind, Bifurcation::Kind::fold);
  EXPECT_NEAR(fold.at.speed, 807.55, 0.005 * 807.55);
  for (std::size_t i = 1; i < whirl.orbits.size(); ++i) EXPECT_EQ(whirl.orbits[i].stable, i > fold.after) << i;
  const SteadyState& last = whirl.orbits.back();
  EXPECT_TRUE(last.speed > threshold);
  EXPECT_GT(std::hypot(last.X(4), last.X(8)), 0.7 * friswell.clearance);
  for (std::size_t i = 1; i < whirl.orbits.size(); ++i) {
    const SteadyState& o = whirl.orbits[i];
    EXPECT_LT(o.residual, 1e-9) << i;
    const Real ratio = o.frequency / o.speed;
    EXPECT_GT(ratio, 0.3) << i;
    EXPECT_LT(ratio, 0.55) << i;
  }
}

}  // namespace
}  // namespace feran::test_orbits

namespace feran::test_orbits {
namespace {

// The size of an orbit's first harmonic, whatever its phase.
Real first_harmonic(const SteadyState& o, Index n) {
  return std::sqrt(o.X.segment(n, n).squaredNorm() + o.X.segment(2 * n, n).squaredNorm());
}

// A branch continued from a given orbit: the whip orbit at 950 rad/s of the branch from
// the Hopf point, spoilt (1 % larger, its phase turned by 0.7 rad, its frequency 1 %
// off), is corrected back onto the orbit (first-harmonic size and frequency 1e-8) and
// continued: downwards it meets the same fold (1e-5: two locations, each to the
// continuation's tolerance), upwards its state at 1050 rad/s is the first branch's
// (1e-8). Continued instead in the oil's viscosity at 950 rad/s, its state at
// 0.12 Pa s is the whirl orbit at 950 rad/s of the speed branch of the rotor built with
// 0.12 Pa s (1e-7): one orbit reached by two parameterisations.
TEST(Orbits, ABranchThroughAGivenOrbitIsTheBranchThroughIt) {
  const Real m = 525.0 / g;
  const Model model = rigid_rotor(m);
  const CondensedRotor rotor = condensed(model);
  const Index n = rotor.size();
  OrbitSettings settings;
  settings.continuation.p_min = 600.0;
  settings.continuation.p_max = 1100.0;
  const OrbitBranch eq = equilibrium_branch(rotor, settings);
  settings.fourier = {.harmonics = 8, .samples = 64};
  settings.continuation.max_points = 60;
  const OrbitBranch whirl = hopf_branch(rotor, eq.bifurcations.at(0), settings);
  ASSERT_EQ(whirl.bifurcations.size(), 1U);
  const std::vector<SteadyState> at = states_at(rotor, whirl, 950.0, settings);
  ASSERT_EQ(at.size(), 1U);
  SteadyState given = at[0];
  for (Index k = 1; k <= settings.fourier.harmonics; ++k) {
    const Real c = std::cos(0.7 * static_cast<Real>(k)), s = std::sin(0.7 * static_cast<Real>(k));
    const Vector a = given.X.segment((2 * k - 1) * n, n), b = given.X.segment(2 * k * n, n);
    given.X.segment((2 * k - 1) * n, n) = c * a - s * b;
    given.X.segment(2 * k * n, n) = s * a + c * b;
  }
  given.X *= 1.01;
  given.frequency *= 1.01;

  const RotorFamily in_speed(rotor);
  const OrbitBranch down = branch_through(in_speed, given, OrbitBranch::Kind::self_excited, settings, true);
  ASSERT_GT(down.orbits.size(), 5U) << down.ended_by;
  EXPECT_NEAR(down.orbits[0].frequency, at[0].frequency, 1e-8 * at[0].frequency);
  EXPECT_NEAR(first_harmonic(down.orbits[0], n), first_harmonic(at[0], n), 1e-8 * first_harmonic(at[0], n));
  ASSERT_FALSE(down.bifurcations.empty()) << down.ended_by;
  EXPECT_EQ(down.bifurcations[0].kind, Bifurcation::Kind::fold);
  EXPECT_NEAR(down.bifurcations[0].at.speed, whirl.bifurcations[0].at.speed, 1e-5 * whirl.bifurcations[0].at.speed);
  const OrbitBranch up = branch_through(in_speed, given, OrbitBranch::Kind::self_excited, settings, false);
  EXPECT_TRUE(up.clipped) << up.ended_by;
  const std::vector<SteadyState> a = states_at(rotor, whirl, 1050.0, settings),
                                 b = states_at(rotor, up, 1050.0, settings);
  ASSERT_EQ(a.size(), 1U);
  ASSERT_EQ(b.size(), 1U);
  EXPECT_NEAR(b[0].frequency, a[0].frequency, 1e-8 * a[0].frequency);
  EXPECT_NEAR(first_harmonic(b[0], n), first_harmonic(a[0], n), 1e-8 * first_harmonic(a[0], n));
  EXPECT_EQ(b[0].stable, a[0].stable);

  const auto with_viscosity = [&](Real mu) {
    JournalBearingGeometry geometry = friswell;
    geometry.viscosity = mu;
    return test::rigid_rotor_in_journal_bearings(m, FilmTheory::short_bearing, geometry);
  };
  const RotorFamily in_viscosity(rotor, 950.0, with_viscosity, "journal_bearings[*].viscosity");
  OrbitSettings v = settings;
  v.continuation.p_min = 0.05;
  v.continuation.p_max = 0.2;
  SteadyState from = at[0];
  from.parameter = friswell.viscosity;
  const OrbitBranch thicker = branch_through(in_viscosity, from, OrbitBranch::Kind::self_excited, v, false);
  const std::vector<SteadyState> by_viscosity = states_at(in_viscosity, thicker, 0.12, v);
  ASSERT_EQ(by_viscosity.size(), 1U) << thicker.ended_by;
  const Model other = with_viscosity(0.12);
  const CondensedRotor other_rotor = condensed(other);
  const OrbitBranch other_eq = equilibrium_branch(other_rotor, settings);
  const OrbitBranch other_whirl = hopf_branch(other_rotor, other_eq.bifurcations.at(0), settings);
  const std::vector<SteadyState> by_speed = states_at(other_rotor, other_whirl, 950.0, settings);
  ASSERT_FALSE(by_speed.empty()) << other_whirl.ended_by;
  const SteadyState& large = by_speed.back();
  EXPECT_NEAR(by_viscosity[0].frequency, large.frequency, 1e-7 * large.frequency);
  EXPECT_NEAR(first_harmonic(by_viscosity[0], n), first_harmonic(large, n), 1e-7 * first_harmonic(large, n));
}

// Continuation in a number of the model at a fixed speed: the oil's viscosity, at the
// speed of the Hopf point found in speed (viscosity 0.1 Pa s). The equilibrium branch
// in viscosity from 0.05 to 0.2 Pa s meets its Hopf point at 0.1 Pa s (1e-5 relative:
// two locations, each to about 1e-6), and the self-excited branch leaves it with
// orbits that solve the balance (1e-9), each model condensed on the first's basis.
TEST(Orbits, ContinuationInViscosityMeetsTheSameHopfPoint) {
  const Real m = 525.0 / g;
  const Model model = rigid_rotor(m);
  const CondensedRotor rotor = condensed(model);
  OrbitSettings settings;
  settings.continuation.p_min = 600.0;
  settings.continuation.p_max = 1100.0;
  const Real speed = equilibrium_branch(rotor, settings).bifurcations.at(0).at.speed;
  const auto with_viscosity = [&](Real mu) {
    JournalBearingGeometry geometry = friswell;
    geometry.viscosity = mu;
    return test::rigid_rotor_in_journal_bearings(m, FilmTheory::short_bearing, geometry);
  };
  const Model first = with_viscosity(0.05);
  const CondensedRotor base = condensed(first);
  const RotorFamily family(base, speed, with_viscosity, "journal_bearings[*].viscosity");
  settings.continuation.p_min = 0.05;
  settings.continuation.p_max = 0.2;
  const OrbitBranch eq = equilibrium_branch(family, settings);
  ASSERT_EQ(eq.bifurcations.size(), 1U) << eq.ended_by;
  EXPECT_EQ(eq.bifurcations[0].kind, Bifurcation::Kind::hopf);
  EXPECT_NEAR(eq.bifurcations[0].at.parameter, 0.1, 1e-5 * 0.1);
  EXPECT_NEAR(eq.bifurcations[0].at.speed, speed, 1e-12 * speed);
  settings.fourier = {.harmonics = 6, .samples = 48};
  settings.continuation.max_points = 12;
  const OrbitBranch whirl = hopf_branch(family, eq.bifurcations[0], settings);
  ASSERT_GT(whirl.orbits.size(), 5U) << whirl.ended_by;
  for (std::size_t i = 1; i < whirl.orbits.size(); ++i) EXPECT_LT(whirl.orbits[i].residual, 1e-9) << i;
}

// A model the parameter path cannot build beyond a value (a door's checks refusing
// it) ends the branch there with the model's reason, keeping the states found.
TEST(Orbits, ABranchIntoValuesTheModelRefusesKeepsItsStatesAndSaysWhy) {
  const Real m = 525.0 / g;
  const auto with_viscosity = [&](Real mu) {
    if (mu > 0.15) throw Error("journal_bearings[0].viscosity: above the oil's range");
    JournalBearingGeometry geometry = friswell;
    geometry.viscosity = mu;
    return test::rigid_rotor_in_journal_bearings(m, FilmTheory::short_bearing, geometry);
  };
  const Model first = with_viscosity(0.05);
  const CondensedRotor base = condensed(first);
  const RotorFamily family(base, 900.0, with_viscosity, "journal_bearings[*].viscosity");
  OrbitSettings settings;
  settings.continuation.p_min = 0.05;
  settings.continuation.p_max = 0.2;
  const OrbitBranch eq = equilibrium_branch(family, settings);
  ASSERT_GT(eq.orbits.size(), 5U) << eq.ended_by;
  EXPECT_FALSE(eq.clipped);
  EXPECT_LE(eq.orbits.back().parameter, 0.15);
  EXPECT_GT(eq.orbits.back().parameter, 0.149);
  EXPECT_NE(eq.ended_by.find("above the oil's range"), std::string::npos) << eq.ended_by;
  EXPECT_NE(eq.ended_by.find("cannot be evaluated just beyond"), std::string::npos) << eq.ended_by;
}

// Duffing's oscillator m x'' + c x' + k x + k₃x³ = F cos Ωt as a rotor: a point mass on
// a spring and damper moving in y alone, the cubic spring a force, F a synchronous
// harmonic force. Its forced branch with one harmonic meets the closed-form
// single-harmonic frequency response [(k − mΩ²)A + ¾k₃A³]² + (cΩA)² = F² at every
// orbit (1e-8, the balance's tolerance with the curve's conditioning), and its two
// folds are where the cubic in A² has a double root (1e-6 in Ω: located to the
// continuation's tolerance, the speed derivative by differences).
TEST(Orbits, ForcedDuffingRotorFollowsItsFrequencyResponseThroughBothFolds) {
  using namespace test::duffing;  // NOLINT(google-build-using-namespace): the shared case's names
  const Model model = rotor_model();
  const CondensedRotor rotor = condense(model);
  ASSERT_EQ(rotor.size(), 1);
  const OrbitSettings settings = branch_settings();
  const OrbitBranch b = forced_branch(rotor, settings);
  EXPECT_TRUE(b.clipped) << b.ended_by;
  for (const SteadyState& o : b.orbits) {
    EXPECT_NEAR(test::duffing::response_curve(o.speed, std::hypot(o.X(1), o.X(2))), F * F, 1e-8 * F * F) << o.speed;
  }
  // The folds of the closed form: the discriminant of the cubic in u = A² vanishes.
  const std::vector<Real> expected = test::duffing::closed_form_folds();
  ASSERT_EQ(expected.size(), 2U);
  std::vector<Real> folds;
  for (const Bifurcation& f : b.bifurcations)
    if (f.kind == Bifurcation::Kind::fold) folds.push_back(f.at.speed);
  ASSERT_EQ(folds.size(), 2U);
  EXPECT_NEAR(folds[0], expected[1], 1e-6);  // the jump-down, met first on the way up
  EXPECT_NEAR(folds[1], expected[0], 1e-6);
  // Between the folds the orbits are unstable (the middle branch), elsewhere stable.
  for (std::size_t i = 0; i < b.orbits.size(); ++i) {
    const bool middle = i > b.bifurcations.front().after && i <= b.bifurcations.back().after;
    EXPECT_EQ(b.orbits[i].stable, !middle) << i;
  }
}

// Internal (rotating) damping destabilises a Jeffcott rotor above
// Ω = ω_n(1 + c_e/c_i): the Hopf point of the equilibrium branch, to 1e-6.
TEST(Orbits, InternalDampingHopfIsAtTheClosedFormSpeed) {
  const Real ce = 100.0, ci = 300.0;
  const Model model = test::jeffcott(test::runup_mass, test::runup_stiffness, ce, ci);
  const CondensedRotor rotor(model, nullptr, {});
  const Real wn = std::sqrt(test::runup_stiffness / test::runup_mass);
  OrbitSettings settings;
  settings.continuation.p_min = 0.5 * wn;
  settings.continuation.p_max = 3.0 * wn;
  const OrbitBranch eq = equilibrium_branch(rotor, settings);
  ASSERT_EQ(eq.bifurcations.size(), 1U);
  EXPECT_EQ(eq.bifurcations[0].kind, Bifurcation::Kind::hopf);
  EXPECT_NEAR(eq.bifurcations[0].at.speed, wn * (1 + ce / ci), 1e-6 * wn);
}

// Two Jeffcott rotors side by side (ω_2 = 2ω_1), each with internal damping: the
// equilibrium loses stability at ω_1(1 + c_e/c_i) and, already unstable, loses it once
// more at ω_2(1 + c_e/c_i), where the second rotor's forward whirl crosses too. Both
// Hopf points are found and located: the first to 1e-6 of ω_1, the second to 2e-6 of
// its speed (measured 1.2e-6: the stability limit 1e-7 on Re s/|s| sits that far from
// Re s = 0 where the second mode's damping changes slowly with speed). The second is
// missed by a test of the largest exponent alone, which stays positive past the first.
TEST(Orbits, ASecondHopfPointOnAnAlreadyUnstableEquilibriumIsFound) {
  const Real ce = 100.0, ci = 300.0, m = test::runup_mass, k = test::runup_stiffness;
  Model model = test::jeffcott(m, k, ce, ci);
  const Index n = test::add_node(model, 1.0, true, "second disk");
  test::add_body(model, n, m, 1e-3, 1e-3);
  test::add_isotropic_bearing(model, n, 4 * k, ce);
  model.elements.emplace_back(RotatingDamper(n, std::nullopt, {ci, 0, 0, 0}));
  test::fix(model, n, {Dof::u, Dof::rx, Dof::ry, Dof::rz});
  const CondensedRotor rotor(model, nullptr, {});
  const Real w1 = std::sqrt(k / m);
  OrbitSettings settings;
  settings.continuation.p_min = 0.5 * w1;
  settings.continuation.p_max = 3.5 * w1;
  const OrbitBranch eq = equilibrium_branch(rotor, settings);
  ASSERT_EQ(eq.bifurcations.size(), 2U);
  for (const Bifurcation& b : eq.bifurcations) EXPECT_EQ(b.kind, Bifurcation::Kind::hopf);
  EXPECT_NEAR(eq.bifurcations[0].at.speed, w1 * (1 + ce / ci), 1e-6 * w1);
  const Real second = 2 * w1 * (1 + ce / ci);
  EXPECT_NEAR(eq.bifurcations[1].at.speed, second, 2e-6 * second);
  EXPECT_NEAR(critical_frequency(eq.bifurcations[1]), 2 * w1, 1e-6 * w1);
}

// Coulomb friction between rotor and shaft (regularised over 1e-5 m/s) makes the
// Jeffcott rotor whirl above ω_n; the whirl branch leaving the Hopf point settles on
// the closed-form orbit — radius F/(c_e·ω_n), frequency ω_n (the friction force is
// tangential and of constant size on it) — at 2ω_n to 1e-3 (the regularisation's
// ε/((Ω − ω_n)R) ≈ 1.5e-4), and its orbits there are stable.
TEST(Orbits, CoulombFrictionWhirlHasTheClosedFormRadiusAndFrequency) {
  const Real ce = 300.0, F = 20.0;
  const Model model = test::runup_jeffcott(ce, 0.0, 0.0, F);
  const CondensedRotor rotor(model, nullptr,
                             {.modes = 12,
                              .gravity = Eigen::Vector3d::Zero(),
                              .static_loads = false,
                              .unbalance = false,
                              .reference_speed = 0.0});
  const Real wn = std::sqrt(test::runup_stiffness / test::runup_mass);
  OrbitSettings settings;
  settings.continuation.p_min = 0.5 * wn;
  settings.continuation.p_max = 2.5 * wn;
  const OrbitBranch eq = equilibrium_branch(rotor, settings);
  ASSERT_FALSE(eq.bifurcations.empty());
  ASSERT_EQ(eq.bifurcations[0].kind, Bifurcation::Kind::hopf);
  settings.fourier = {.harmonics = 3, .samples = 32};
  settings.length_scale = F / (ce * wn);
  settings.continuation.max_points = 400;
  const OrbitBranch whirl = hopf_branch(rotor, eq.bifurcations[0], settings);
  const std::vector<SteadyState> at = states_at(rotor, whirl, 2 * wn, settings);
  ASSERT_EQ(at.size(), 1U) << whirl.ended_by;
  const Real R = F / (ce * wn);
  const SteadyState& o = at[0];
  const Index n = rotor.size();
  const Real radius = std::hypot(o.X(n), o.X(2 * n));  // the first kept DOF's first harmonic
  EXPECT_NEAR(radius, R, 1e-3 * R);
  EXPECT_NEAR(o.frequency, wn, 1e-3 * wn);
  EXPECT_TRUE(o.stable);
}

}  // namespace
}  // namespace feran::test_orbits

namespace feran::test_orbits {
namespace {

// What the periodic analysis cannot take is refused with the reason: a force with a
// time law of its own (two base frequencies), a hysteretic loss factor (harmonic
// motion only).
TEST(Orbits, RefusesWhatIsNotPeriodicAtTheRotorSpeed) {
  Model own = test::jeffcott(1.0, 1.0, 0.1, 0.0);
  own.forces.emplace_back(HarmonicForce{.node = 0,
                                        .type = HarmonicForce::Kind::fixed,
                                        .direction = Dof::v,
                                        .amplitude = 1.0,
                                        .phase = 0.0,
                                        .frequency = 3.0,
                                        .time_table = {}},
                          "shaker");
  try {
    const CondensedRotor rotor(own, nullptr, {});
    ADD_FAILURE() << "accepted a force at a frequency of its own";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'shaker' follows a time law of its own"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace feran::test_orbits
