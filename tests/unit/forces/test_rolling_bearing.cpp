// Rolling-element bearings: one element against the Hertz law, the load share of a
// loaded bearing against Stribeck's, the Jacobian against differences, and the cage
// kinematics.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <numeric>

#include <feran/forces/rolling_bearing.hpp>

namespace feran::test_rolling_bearing {
namespace {

// A deep-groove ball bearing of 9 balls of 12 mm on a 60 mm pitch circle.
RollingBearingGeometry ball_bearing(Real clearance = 0.0) {
  return {.elements = 9,
          .element_diameter = 0.012,
          .pitch_diameter = 0.06,
          .contact_angle = 0.0,
          .clearance = clearance,
          .hertz_constant = 1e10,
          .roller = false};
}

Eigen::Vector2d force_on_journal(const RollingBearing& b, const Eigen::Vector2d& x, Real angle = 0.0) {
  return b.force({.t = 0, .speed = 0, .acceleration = 0, .angle = angle}, x, Vector::Zero(2)).f.head<2>();
}

TEST(RollingBearing, OneElementInContactFollowsTheHertzLaw) {
  // With a clearance of 20 µm and the journal pushed along element 0 by x below
  // 20 µm / cos 40° = 26.1 µm (its neighbours sit 40° away), only element 0 touches:
  // the force is K·(x − c)^{3/2} (ball) or K·(x − c)^{10/9} (roller), along −x, to
  // round-off.
  for (const bool roller : {false, true}) {
    RollingBearingGeometry g = ball_bearing(20e-6);
    g.roller = roller;
    const RollingBearing b{.node_a = 0, .node_b = {}, .geometry = g};
    for (const Real x : {21e-6, 23e-6, 26e-6}) {
      const Eigen::Vector2d f = force_on_journal(b, Eigen::Vector2d(x, 0.0));
      const Real expected = g.hertz_constant * std::pow(x - 20e-6, roller ? 10.0 / 9.0 : 1.5);
      EXPECT_NEAR(f(0), -expected, 1e-13 * expected) << x;
      EXPECT_NEAR(f(1), 0.0, 1e-13 * expected);
      const std::vector<Real> q = element_loads(g, Eigen::Vector2d(x, 0.0), 0.0);
      EXPECT_EQ(std::count_if(q.begin(), q.end(), [](Real v) { return v > 0; }), 1);
    }
  }
}

TEST(RollingBearing, LoadShareOfAZeroClearanceBearingIsStribecks) {
  // Zero clearance, an element on the load line: δ_j = δ_max cos ψ_j, so
  // Q_j = Q_max cos^{3/2} ψ_j and F_r = Q_max Σ cos^{5/2} ψ_j over |ψ_j| < 90°
  // (Stribeck 1901). Exactly so for Z = 9; and for many elements Σ → Z/4.37, the
  // constant of Q_max = 4.37 F_r/Z (Harris & Kotzalas 2007, §7.2): Z = 400 within 0.1 %.
  for (const int Z : {9, 400}) {
    RollingBearingGeometry g = ball_bearing();
    g.elements = Z;
    const RollingBearing b{.node_a = 0, .node_b = {}, .geometry = g};
    const Eigen::Vector2d x(5e-6, 0.0);
    const Real Fr = -force_on_journal(b, x)(0);
    const std::vector<Real> q = element_loads(g, x, 0.0);
    const Real q_max = *std::max_element(q.begin(), q.end());
    Real share = 0.0;
    for (int j = 0; j < Z; ++j) {
      const Real c = std::cos(2 * pi * j / Z);
      if (c > 0) share += std::pow(c, 2.5);
    }
    EXPECT_NEAR(Fr, q_max * share, 1e-12 * Fr) << Z;
    if (Z == 400) {
      EXPECT_NEAR(q_max * Z / Fr, 4.37, 0.001 * 4.37);
    }
  }
}

TEST(RollingBearing, JacobianEqualsCentralDifferencesAndHousingTakesTheOpposite) {
  // Steps of 1e-9 m on deflections of micrometres: 1e-6 of the block's norm.
  RollingBearingGeometry g = ball_bearing(2e-6);
  g.contact_angle = 0.3;
  const RollingBearing b{.node_a = 0, .node_b = 1, .geometry = g};
  Vector x(4);
  x << 6e-6, -3e-6, 0.5e-6, 0.2e-6;
  const MotionState s{.t = 0, .speed = 100, .acceleration = 0, .angle = 0.7};
  const NonlinearForceValue f = b.force(s, x, Vector::Zero(4));
  Matrix fd(4, 4);
  for (int k = 0; k < 4; ++k) {
    Vector e = Vector::Zero(4);
    e(k) = 1e-9;
    fd.col(k) = (b.force(s, x + e, Vector::Zero(4)).f - b.force(s, x - e, Vector::Zero(4)).f) / 2e-9;
  }
  EXPECT_LT((f.dfdx - fd).norm(), 1e-6 * f.dfdx.norm());
  EXPECT_LT((f.f.head<2>() + f.f.tail<2>()).norm(), 1e-12 * f.f.norm());
  EXPECT_EQ(f.dfdv.norm(), 0.0);
}

TEST(RollingBearing, CageTurnsAtTheKinematicRatioAndTheStiffnessRepeatsAtTheBallPass) {
  // Rolling without slip, outer race at rest: the cage turns at (1 − (d/D_p) cos α)/2
  // of the shaft speed; here 0.4. The force at a fixed displacement repeats when the
  // cage has advanced by one element spacing, after a shaft angle of 2π/(Z·0.4), and
  // varies in between (the varying compliance).
  const RollingBearingGeometry g = ball_bearing();
  EXPECT_NEAR(g.cage_ratio(), 0.4, 1e-15);
  EXPECT_NEAR(g.ball_pass_ratio(), 3.6, 1e-14);
  const RollingBearing b{.node_a = 0, .node_b = {}, .geometry = g};
  const Eigen::Vector2d x(5e-6, 0.0);
  const Real period = 2 * pi / g.ball_pass_ratio();
  const Eigen::Vector2d f0 = force_on_journal(b, x, 0.3), f1 = force_on_journal(b, x, 0.3 + period),
                        fh = force_on_journal(b, x, 0.3 + 0.5 * period);
  EXPECT_LT((f0 - f1).norm(), 1e-12 * f0.norm());
  EXPECT_GT((f0 - fh).norm(), 1e-3 * f0.norm());
}

// The most loaded element, the loaded count, and Hertz's contact stress of a sphere of
// radius R on a steel plane: with K = (4/3)E*√R, p_max = (6QE*²/(π³R²))^(1/3)
// (Johnson, Contact Mechanics, 1985, eq. 4.24), a form independent of the one coded.
TEST(RollingBearing, OperatingDataGiveTheMostLoadedElementAndItsHertzStress) {
  const Real E_star = 210e9 / (2 * (1 - 0.09)), radius = 0.004;
  RollingBearingGeometry g = ball_bearing();
  g.hertz_constant = 4.0 / 3.0 * E_star * std::sqrt(radius);
  const RollingBearing b{.node_a = 0, .node_b = {}, .geometry = g};
  Vector x(2);
  x << 2e-5, 0.0;
  std::map<std::string, Real> d;
  for (const OperatingValue& o : b.operating_data({}, x, Vector::Zero(2))) d[o.name] = o.value;
  const std::vector<Real> Q = element_loads(g, Eigen::Vector2d(x), 0.0);
  const Real q = *std::max_element(Q.begin(), Q.end());
  EXPECT_EQ(d["max_element_load_n"], q);
  EXPECT_EQ(d["loaded_elements"], static_cast<Real>(std::count_if(Q.begin(), Q.end(), [](Real v) { return v > 0; })));
  EXPECT_GT(d["loaded_elements"], 1);
  EXPECT_NEAR(d["max_contact_stress_pa"], std::cbrt(6 * q * E_star * E_star / (pi * pi * pi * radius * radius)),
              1e-12 * d["max_contact_stress_pa"]);
  g.roller = true;
  const RollingBearing r{.node_a = 0, .node_b = {}, .geometry = g};
  EXPECT_TRUE(std::isnan(r.operating_data({}, x, Vector::Zero(2)).back().value));
}

}  // namespace
}  // namespace feran::test_rolling_bearing
