// Unit tests of the rigid body element (docs/theory/rigid_body.md): mass properties of
// disks, the mass matrix with an axial centre-of-mass offset checked through the
// kinetic energy, and the gyroscopic matrix of the polar inertia.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Dense>

#include <feran/elements/rigid_body.hpp>

namespace feran::test_rigid_body {
namespace {

constexpr Index i_of(Dof d) { return static_cast<Index>(d); }

// Solid disk of diameter D and width h, textbook formulas of a uniform cylinder:
// m = ρπD²h/4, J_P = mD²/8, J_A = mD²/16 + mh²/12 (about a diameter through
// the centre).
RigidBodyProperties solid_disk(Real rho, Real D, Real h) {
  RigidBodyProperties p;
  p.mass = rho * pi * D * D * h / 4.0;
  p.polar_inertia = p.mass * D * D / 8.0;
  p.transverse_inertia = p.mass * D * D / 16.0 + p.mass * h * h / 12.0;
  return p;
}

// Mass properties: solid disk against the textbook formulas, and an annular disk as
// the solid disk minus its bore (an independent route to the annulus formulas).
// Tolerance 1e-14 relative: the same quantities through a different order of
// products.
TEST(RigidBody, DiskMassProperties) {
  const Real rho = 7810, D = 0.35, d = 0.05, h = 0.07;
  const RigidBodyProperties solid = RigidBody::disk(rho, D, 0.0, h);
  const RigidBodyProperties ref = solid_disk(rho, D, h);
  EXPECT_NEAR(solid.mass, ref.mass, 1e-14 * ref.mass);
  EXPECT_NEAR(solid.polar_inertia, ref.polar_inertia, 1e-14 * ref.polar_inertia);
  EXPECT_NEAR(solid.transverse_inertia, ref.transverse_inertia, 1e-14 * ref.transverse_inertia);
  EXPECT_EQ(solid.offset, 0.0);

  const RigidBodyProperties ring = RigidBody::disk(rho, D, d, h);
  const RigidBodyProperties bore = solid_disk(rho, d, h);
  EXPECT_NEAR(ring.mass, ref.mass - bore.mass, 1e-14 * ref.mass);
  EXPECT_NEAR(ring.polar_inertia, ref.polar_inertia - bore.polar_inertia, 1e-14 * ref.polar_inertia);
  EXPECT_NEAR(ring.transverse_inertia, ref.transverse_inertia - bore.transverse_inertia,
              1e-14 * ref.transverse_inertia);

  // Hand values for the 350 × 70 mm disk with a 50 mm bore (Friswell's example 5.9.1
  // disk 2): m = 7810·π/4·(0.35² − 0.05²)·0.07 = 51.53 kg, J_P = m(R² + r²)/2
  // = 0.8051 kg m², J_A = m(R² + r²)/4 + mh²/12 = 0.4236 kg m². Tolerance: half a
  // unit in the last digit given.
  EXPECT_NEAR(ring.mass, 51.53, 0.005);
  EXPECT_NEAR(ring.polar_inertia, 0.8051, 0.00005);
  EXPECT_NEAR(ring.transverse_inertia, 0.4236, 0.00005);
}

// The mass matrix with an axial centre-of-mass offset e is the one whose kinetic
// energy is ½m|v_cg|² + ½J_P·ṙx² + ½J_cg(ṙy² + ṙz²), with v_cg = v' + e·rz',
// w_cg = w' − e·ry' (rz = +dv/dx, ry = −dw/dx) and J_cg = J_A − m e² (parallel axis:
// J_A is about the node). Checked on random velocity vectors; tolerance 1e-13
// relative (a sum of a dozen products).
TEST(RigidBody, OffsetMassMatrixGivesTheKineticEnergy) {
  const RigidBodyProperties p{9.1, 0.0219, 0.035, 0.03};
  const LocalMatrices lm = RigidBody(2, p, true).local_matrices({});
  ASSERT_EQ(lm.dofs.size(), 6u);
  for (std::size_t d = 0; d < 6; ++d) EXPECT_EQ(lm.dofs[d], 12 + static_cast<Index>(d));
  ASSERT_EQ(lm.M.rows(), 6);

  const Real m = p.mass, e = p.offset, Jcg = p.transverse_inertia - m * e * e;
  ASSERT_GT(Jcg, 0.0);
  std::mt19937 gen(42);
  std::uniform_real_distribution<Real> dist(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Vector qd(6);
    for (Index k = 0; k < 6; ++k) qd(k) = dist(gen);
    const Real u = qd(i_of(Dof::u)), v = qd(i_of(Dof::v)), w = qd(i_of(Dof::w)), rx = qd(i_of(Dof::rx)),
               ry = qd(i_of(Dof::ry)), rz = qd(i_of(Dof::rz));
    const Real vcg = v + e * rz, wcg = w - e * ry;
    const Real T =
        0.5 * m * (u * u + vcg * vcg + wcg * wcg) + 0.5 * p.polar_inertia * rx * rx + 0.5 * Jcg * (ry * ry + rz * rz);
    EXPECT_NEAR(0.5 * qd.dot(lm.M * qd), T, 1e-13 * T) << "trial " << trial;
  }
  EXPECT_LE((lm.M - lm.M.transpose()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix>(lm.M).eigenvalues().minCoeff(), 0.0);
  // No stiffness or damping from a rigid body.
  EXPECT_TRUE(lm.K.size() == 0 || lm.K.isZero(0.0));
  EXPECT_TRUE(lm.C.size() == 0 || lm.C.isZero(0.0));
}

// Gyroscopic matrix of the spinning body (paper eq. 2, whose signs the text lost; the
// sign follows from the angular momentum below; DOF names as in
// docs/theory/conventions.md): G(ry, rz) = +J_P, G(rz, ry) = −J_P, nothing else,
// independent of the offset. Exact entries.
TEST(RigidBody, GyroscopicMatrixOfThePolarInertia) {
  const RigidBodyProperties p{1.93, 0.0063, 0.0104, -0.02};
  const LocalMatrices lm = RigidBody(0, p, true).local_matrices({});
  ASSERT_EQ(lm.G.rows(), 6);
  EXPECT_EQ(lm.G(i_of(Dof::rz), i_of(Dof::ry)), -p.polar_inertia);
  EXPECT_EQ(lm.G(i_of(Dof::ry), i_of(Dof::rz)), p.polar_inertia);
  Matrix rest = lm.G;
  rest(i_of(Dof::rz), i_of(Dof::ry)) = rest(i_of(Dof::ry), i_of(Dof::rz)) = 0.0;
  EXPECT_TRUE(rest.isZero(0.0));

  // Physical sign: the spin axis of a body tilted by (ry, rz) points along
  // (1, rz, −ry), so H = J_P·Ω·(1, rz, −ry) + J_A·(0, ṙy, ṙz) and the moment about +y
  // is dH_y/dt = J_A·r̈y + J_P·Ω·ṙz: a tilt rate ṙz = 1 needs +J_P per unit speed.
  Vector qd = Vector::Zero(6);
  qd(i_of(Dof::rz)) = 1.0;
  EXPECT_EQ((lm.G * qd)(i_of(Dof::ry)), p.polar_inertia);
}

// A non-rotating body (stator) has no gyroscopic matrix.
TEST(RigidBody, NonRotatingBodyHasNoGyroscopicMatrix) {
  const RigidBodyProperties p{5.0, 0.01, 0.01, 0.0};
  const LocalMatrices lm = RigidBody(1, p, false).local_matrices({});
  EXPECT_TRUE(lm.G.size() == 0 || lm.G.isZero(0.0));
  EXPECT_EQ(lm.M(i_of(Dof::v), i_of(Dof::v)), 5.0);
  EXPECT_EQ(lm.M(i_of(Dof::rx), i_of(Dof::rx)), 0.01);
  EXPECT_FALSE(RigidBody(1, p, false).speed_dependent());
}

}  // namespace
}  // namespace feran::test_rigid_body
