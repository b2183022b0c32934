// Unit tests of the linear spring–damper (docs/theory/spring_damper.md): matrices of
// node-to-ground and node-to-node elements, where the cross-coupled bearing terms
// land, and coefficients that depend on speed. All entries are copies or single
// interpolations of the coefficients, so comparisons are exact unless noted.
#include <gtest/gtest.h>

#include <cmath>

#include <feran/elements/spring_damper.hpp>

namespace feran::test_spring_damper {
namespace {

constexpr std::size_t at(Dof d) { return static_cast<std::size_t>(d); }
constexpr Index i_of(Dof d) { return static_cast<Index>(d); }

SpringDamperCoefficients direct_coefficients() {
  SpringDamperCoefficients c;
  const Real k[6] = {1e5, 2e6, 3e6, 400.0, 500.0, 600.0};
  const Real d[6] = {10.0, 20.0, 30.0, 0.4, 0.5, 0.6};
  for (std::size_t i = 0; i < 6; ++i) {
    c.k[i] = k[i];
    c.c[i] = d[i];
  }
  return c;
}

// Node to ground: K = diag(k), C = diag(c) on the node's six DOFs, in DOF order.
TEST(SpringDamper, NodeToGround) {
  const SpringDamper s(3, std::nullopt, direct_coefficients());
  const LocalMatrices lm = s.local_matrices({});
  ASSERT_EQ(lm.dofs.size(), 6u);
  for (std::size_t d = 0; d < 6; ++d) EXPECT_EQ(lm.dofs[d], 18 + static_cast<Index>(d));
  Matrix K = Matrix::Zero(6, 6), C = Matrix::Zero(6, 6);
  K.diagonal() << 1e5, 2e6, 3e6, 400.0, 500.0, 600.0;
  C.diagonal() << 10.0, 20.0, 30.0, 0.4, 0.5, 0.6;
  EXPECT_EQ(lm.K, K);
  EXPECT_EQ(lm.C, C);
  EXPECT_TRUE(lm.M.size() == 0 || lm.M.isZero(0.0));
  EXPECT_TRUE(lm.G.size() == 0 || lm.G.isZero(0.0));
  EXPECT_FALSE(s.speed_dependent());
}

// Node to node: the element acts on the relative motion Δ = q_a − q_b, so
// K = [k, −k; −k, k]; moving both nodes together costs no force.
TEST(SpringDamper, NodeToNode) {
  const SpringDamper s(1, 4, direct_coefficients());
  const LocalMatrices lm = s.local_matrices({});
  ASSERT_EQ(lm.dofs.size(), 12u);
  for (std::size_t d = 0; d < 6; ++d) {
    EXPECT_EQ(lm.dofs[d], 6 + static_cast<Index>(d));
    EXPECT_EQ(lm.dofs[d + 6], 24 + static_cast<Index>(d));
  }
  Matrix k = Matrix::Zero(6, 6), c = Matrix::Zero(6, 6);
  k.diagonal() << 1e5, 2e6, 3e6, 400.0, 500.0, 600.0;
  c.diagonal() << 10.0, 20.0, 30.0, 0.4, 0.5, 0.6;
  Matrix K(12, 12), C(12, 12);
  K << k, -k, -k, k;
  C << c, -c, -c, c;
  EXPECT_EQ(lm.K, K);
  EXPECT_EQ(lm.C, C);
  Vector q(12);
  q << 1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6;
  // Equal motion of both nodes stretches nothing: zero force to round-off (not
  // exactly zero where the compiler fuses k·q − k·q into one FMA, which leaves the
  // rounding error of one product: ~1e-16 of ‖K‖·‖q‖).
  EXPECT_LE((lm.K * q).norm(), 1e-14 * lm.K.norm() * q.norm());
  EXPECT_LE((lm.C * q).norm(), 1e-14 * lm.C.norm() * q.norm());
}

// Cross-coupled bearing terms: the force on node a along y is −(k_yy·Δv + k_yz·Δw),
// along z −(k_zy·Δv + k_zz·Δw), so K(v, w) = k_yz and K(w, v) = k_zy (and the same for
// damping). Deliberately unsymmetric values, as in a fluid-film bearing.
TEST(SpringDamper, CrossCoupledTermsLandAtVW) {
  SpringDamperCoefficients sc;
  sc.k[at(Dof::v)] = 1e7;
  sc.k[at(Dof::w)] = 2e7;
  sc.kyz = 3e6;
  sc.kzy = -4e6;
  sc.cyz = 50.0;
  sc.czy = -70.0;
  const LocalMatrices ground = SpringDamper(0, std::nullopt, sc).local_matrices({});
  EXPECT_EQ(ground.K(i_of(Dof::v), i_of(Dof::w)), 3e6);
  EXPECT_EQ(ground.K(i_of(Dof::w), i_of(Dof::v)), -4e6);
  EXPECT_EQ(ground.C(i_of(Dof::v), i_of(Dof::w)), 50.0);
  EXPECT_EQ(ground.C(i_of(Dof::w), i_of(Dof::v)), -70.0);

  // Force on node a (= −K·q) for Δw = 1 only: −k_yz along y and −k_zz along z.
  const LocalMatrices two = SpringDamper(0, 1, sc).local_matrices({});
  Vector q = Vector::Zero(12);
  q(i_of(Dof::w)) = 1.0;
  const Vector f = -two.K * q;
  EXPECT_EQ(f(i_of(Dof::v)), -3e6);
  EXPECT_EQ(f(i_of(Dof::w)), -2e7);
  EXPECT_EQ(f(6 + i_of(Dof::v)), 3e6);  // reaction on node b
  // Only the (v, w) pair is coupled.
  Matrix rest = ground.K;
  rest(i_of(Dof::v), i_of(Dof::w)) = rest(i_of(Dof::w), i_of(Dof::v)) = 0.0;
  rest.diagonal().setZero();
  EXPECT_TRUE(rest.isZero(0.0));
}

// Speed-dependent coefficients are evaluated at the operating point's speed.
// Hand values: table (0, 1e6) → (100 rad/s, 2e6) at 25 rad/s gives 1.25e6; a step at
// 50 rad/s gives its upper value at 60 rad/s; the arctan law with f_as = f − 10 Hz
// gives value·(0.55 − 0.9/π·arctan(1)) = value·0.325. Tolerance 1e-15 relative for
// the computed ones (one interpolation or one arctan).
TEST(SpringDamper, SpeedDependentCoefficientsAtTheOperatingPoint) {
  const Real speed = 60.0;  // rad/s
  const Real f_hz = speed / (2.0 * pi);
  SpringDamperCoefficients sc;
  sc.k[at(Dof::v)] = SpeedCoefficient(SpeedCoefficient::Table{{0.0, 100.0}, {1e6, 2e6}});
  sc.k[at(Dof::w)] = 7e5;
  sc.c[at(Dof::w)] = SpeedCoefficient(SpeedCoefficient::Step{10.0, 20.0, 50.0});
  sc.kyz = SpeedCoefficient(SpeedCoefficient::Arctan{4e5, f_hz - 10.0});
  const SpringDamper s(2, std::nullopt, sc);
  EXPECT_TRUE(s.speed_dependent());

  const LocalMatrices lo = s.local_matrices({25.0});
  EXPECT_NEAR(lo.K(i_of(Dof::v), i_of(Dof::v)), 1.25e6, 1e-15 * 1.25e6);
  EXPECT_EQ(lo.C(i_of(Dof::w), i_of(Dof::w)), 10.0);

  const LocalMatrices hi = s.local_matrices({speed});
  EXPECT_NEAR(hi.K(i_of(Dof::v), i_of(Dof::v)), 1.6e6, 1e-15 * 1.6e6);
  EXPECT_EQ(hi.K(i_of(Dof::w), i_of(Dof::w)), 7e5);
  EXPECT_EQ(hi.C(i_of(Dof::w), i_of(Dof::w)), 20.0);
  EXPECT_NEAR(hi.K(i_of(Dof::v), i_of(Dof::w)), 4e5 * 0.325, 1e-14 * 4e5);
  EXPECT_EQ(hi.K, s.stiffness_6x6(speed));
  EXPECT_EQ(hi.C, s.damping_6x6(speed));
}

// speed_dependent() is true exactly when some coefficient follows a law other than
// a constant, whichever coefficient it is.
TEST(SpringDamper, SpeedDependentOnlyWithANonConstantLaw) {
  const SpeedCoefficient table(SpeedCoefficient::Table{{0.0, 10.0}, {1.0, 2.0}});
  EXPECT_FALSE(SpringDamper(0, 1, direct_coefficients()).speed_dependent());
  for (std::size_t d = 0; d < 6; ++d) {
    SpringDamperCoefficients k = direct_coefficients(), c = direct_coefficients();
    k.k[d] = table;
    c.c[d] = table;
    EXPECT_TRUE(SpringDamper(0, 1, k).speed_dependent()) << "k " << d;
    EXPECT_TRUE(SpringDamper(0, 1, c).speed_dependent()) << "c " << d;
  }
  for (SpeedCoefficient SpringDamperCoefficients::*cross :
       {&SpringDamperCoefficients::kyz, &SpringDamperCoefficients::kzy, &SpringDamperCoefficients::cyz,
        &SpringDamperCoefficients::czy}) {
    SpringDamperCoefficients sc = direct_coefficients();
    sc.*cross = SpeedCoefficient(SpeedCoefficient::Step{1.0, 2.0, 5.0});
    EXPECT_TRUE(SpringDamper(0, std::nullopt, sc).speed_dependent());
    sc.*cross = 3.0;  // a constant cross term is not speed dependent
    EXPECT_FALSE(SpringDamper(0, std::nullopt, sc).speed_dependent());
  }
}

}  // namespace
}  // namespace feran::test_spring_damper
