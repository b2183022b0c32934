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
//   the balance to 1e-9.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/periodic/orbits.hpp>
#include <feran/analyses/static/equilibrium.hpp>

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
  return CondensedRotor(model, nullptr, {.modes = 12, .gravity = model.gravity, .static_loads = true,
                                         .unbalance = false, .reference_speed = 500.0});
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
  for (std::size_t i = 1; i < whirl.orbits.size(); ++i)
    EXPECT_EQ(whirl.orbits[i].stable, i > fold.after) << i;
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
