// Undamped critical speeds and the critical speed map against closed forms: the
// rigid-body modes of a shaft on soft bearings, the Rayleigh beam pinned at both ends,
// and the Campbell diagram's forward crossings of the undamped rotor (another method).
#include <cmath>

#include <gtest/gtest.h>

#include <feran/analyses/api684/critical_speed_map.hpp>
#include <feran/analyses/campbell/campbell.hpp>
#include <feran/core/error.hpp>

#include "test_models.hpp"

namespace feran::test_critical_speed_map {
namespace {

using test::add_isotropic_bearing;
using test::add_shaft;
using test::steel;

constexpr Real L = 1.0, d = 0.05;

// A uniform steel shaft on isotropic bearings at both ends, axial and torsional
// motion held at the first node.
Model shaft_on_bearings(Real k, int n_el = 20, BeamOptions opt = {}) {
  Model m;
  add_shaft(m, 0.0, L, n_el, d, steel(), 0.0, opt);
  add_isotropic_bearing(m, 0, k);
  add_isotropic_bearing(m, n_el, k);
  test::fix(m, 0, {Dof::u, Dof::rx});
  return m;
}

TEST(UndampedCriticals, ARigidShaftOnSoftBearingsBouncesAndRocksAtTheClosedForms) {
  // k = 100 N/m against a shaft stiffness 48EI/L³ ≈ 3e6 N/m: the rotor is rigid to
  // 3e-5 in ω. Bounce ω² = 2k/m; forward synchronous rocking (gyroscopic moments
  // included) ω² = 2k(L/2)²/(I_d − I_p), I_d = m(L²/12 + r²/4), I_p = m r²/2.
  const Real k = 100;
  const Real rho = steel().rho, r = d / 2, m = rho * pi * r * r * L;
  const Real id = m * (L * L / 12 + r * r / 4), ip = m * r * r / 2;
  const auto c = undamped_critical_speeds(shaft_on_bearings(k), 2);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].speed / std::sqrt(2 * k / m) - 1, 0, 1e-4);
  EXPECT_NEAR(c[1].speed / std::sqrt(2 * k * L * L / 4 / (id - ip)) - 1, 0, 1e-4);
  EXPECT_GT(c[0].directivity, 0.99);
  // Without the gyroscopic moments, the rocking frequency at rest uses I_d alone.
  const auto rest = undamped_critical_speeds(shaft_on_bearings(k), 2, false);
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_NEAR(rest[1].speed / std::sqrt(2 * k * L * L / 4 / id) - 1, 0, 1e-4);
}

TEST(UndampedCriticals, APinnedRayleighShaftWhirlsAtTheGyroscopicClosedForm) {
  // Rigid bearings (1e13 N/m against 3e6) and no shear deformation: a Rayleigh beam,
  // simply supported, whose forward synchronous whirl satisfies
  // ρAω² + ρIk²ω² − 2ρIk²Ωω = EIk⁴ at Ω = ω: ω² = EIk⁴/(ρ(A − Ik²)), k = π/L.
  // Twenty cubic elements converge as h⁴: 1e-6 relative.
  BeamOptions opt;
  opt.shear_deformation = false;
  const Real E = steel().E, rho = steel().rho;
  const Real A = pi * d * d / 4, I = pi * std::pow(d, 4) / 64, kw = pi / L;
  const Real expected = std::sqrt(E * I * std::pow(kw, 4) / (rho * (A - I * kw * kw)));
  const auto c = undamped_critical_speeds(shaft_on_bearings(1e13, 20, opt), 1);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].speed / expected - 1, 0, 1e-5);
}

TEST(UndampedCriticals, EqualTheForwardCrossingsOfTheUndampedCampbellDiagram) {
  // Friswell et al. Example 5.9.1 without damping: the 1× crossings of its forward
  // modes, found by Brent's method on tracked eigenvalues (speed tolerance 1e-8
  // relative), are the synchronous solutions found here directly.
  const Model model = test::friswell_5_9_1();
  CampbellOptions options;
  for (int i = 0; i <= 200; ++i) options.speeds.push_back(i * 10.0);
  options.n_modes = 8;
  const CampbellResult campbell = run_campbell(model, options);
  std::vector<Real> forward;
  for (const CriticalSpeed& c : campbell.critical_speeds)
    if (c.whirl == Whirl::forward) forward.push_back(c.speed);
  ASSERT_GE(forward.size(), 2u);
  const auto direct = undamped_critical_speeds(model, static_cast<int>(forward.size()));
  ASSERT_EQ(direct.size(), forward.size());
  for (std::size_t i = 0; i < forward.size(); ++i) EXPECT_NEAR(direct[i].speed / forward[i] - 1, 0, 1e-7) << i;
}

TEST(CriticalSpeedMap, RisesFromTheRigidRotorToThePinnedShaftAndMeetsConstantBearingsAtTheirCriticals) {
  const Model model = shaft_on_bearings(1e7, 10);
  CriticalSpeedMapOptions options;
  options.k_low = 1e2;
  options.k_high = 1e12;
  options.points = 21;
  options.criticals = 3;
  options.curve_stop = 3000;
  options.curve_points = 31;
  const auto map = run_critical_speed_map(model, options);
  ASSERT_TRUE(map.info.converged());
  ASSERT_EQ(map.stiffness.size(), 21u);
  EXPECT_NEAR(map.stiffness.front(), 1e2, 1e-9);
  EXPECT_NEAR(map.stiffness.back() / 1e12 - 1, 0, 1e-12);
  // Each critical speed rises with the bearing stiffness (the Rayleigh quotient of
  // K grows with k, M does not change).
  for (std::size_t i = 1; i < map.stiffness.size(); ++i)
    for (std::size_t n = 0; n < 3; ++n) EXPECT_GT(map.criticals[i][n], map.criticals[i - 1][n]);
  // Curves: both directions of both bearings, constant at 1e7 N/m.
  ASSERT_EQ(map.curves.size(), 4u);
  EXPECT_EQ(map.curves[0].stiffness.front(), 1e7);
  // The intersections of a constant bearing are the rotor's own critical speeds.
  const auto own = undamped_critical_speeds(model, 3);
  int found = 0;
  for (const MapIntersection& x : map.intersections) {
    if (x.speed > 3000) continue;
    ++found;
    EXPECT_NEAR(x.stiffness, 1e7, 1e-3);
    EXPECT_NEAR(x.speed / own[static_cast<std::size_t>(x.critical - 1)].speed - 1, 0, 1e-8);
  }
  EXPECT_GT(found, 0);
}

TEST(CriticalSpeedMap, ASpeedDependentBearingMeetsTheMapWhereItsCriticalIsSelfConsistent) {
  // Bearings stiffening with speed (1e6 N/m at rest, 4e7 N/m at 2000 rad/s): the
  // intersection (Brent's method on the bearing's curve, held at 4e7 N/m beyond the table) and the fixed point of the
  // model's own critical speed (iteration on the coefficients) are two routes to the
  // same speed.
  Model model = shaft_on_bearings(1.0, 10);
  for (auto& e : model.elements) {
    if (e.kind() != "spring_damper") continue;
    const auto* s = e.target<SpringDamper>();
    SpringDamperCoefficients c = s->coefficients();
    SpeedCoefficient::Table t{{0.0, 2000.0}, {1e6, 4e7}};
    c.k[static_cast<std::size_t>(Dof::v)] = SpeedCoefficient(SpeedCoefficient::Law(t));
    c.k[static_cast<std::size_t>(Dof::w)] = SpeedCoefficient(SpeedCoefficient::Law(t));
    e = Element(SpringDamper(s->node_a(), s->node_b(), c));
  }
  CriticalSpeedMapOptions options;
  options.k_low = 1e5;
  options.k_high = 1e9;
  options.points = 5;
  options.criticals = 2;
  options.curve_stop = 4000;  // the second critical lies beyond the table, at 4e7 N/m
  const auto map = run_critical_speed_map(model, options);
  SolverInfo info;
  const auto own = undamped_critical_speeds(model, 2, true, &info);
  ASSERT_TRUE(info.converged()) << info.message;
  int checked = 0;
  for (const MapIntersection& x : map.intersections) {
    if (x.element != map.springs.front() || x.direction != "y") continue;
    EXPECT_NEAR(x.speed / own[static_cast<std::size_t>(x.critical - 1)].speed - 1, 0, 1e-7) << x.critical;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(CriticalSpeedMap, RefusesBadRangesAndARotorWithoutBearings) {
  const Model model = shaft_on_bearings(1e7);
  CriticalSpeedMapOptions options;
  options.k_low = 1e8;
  options.k_high = 1e6;
  EXPECT_THROW(run_critical_speed_map(model, options), Error);
  Model free;
  add_shaft(free, 0.0, L, 4, d, steel());
  EXPECT_THROW(run_critical_speed_map(free, {}), Error);
  EXPECT_THROW(undamped_critical_speeds(free, 2), Error);  // not held laterally
}

}  // namespace
}  // namespace feran::test_critical_speed_map
