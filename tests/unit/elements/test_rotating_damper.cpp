// Unit tests of the rotating (internal) damper (docs/theory/rotating_damper.md).
//
// In the frame rotating with the shaft the damper force is −c·ρ', ρ the rotating-frame
// coordinates (paper eq. 10). Back in inertial coordinates, with J the 90° rotation
// from y to z (J·(v, w) = (−w, v)), the force is −c(r' − Ω·J·r): the damping matrix
// C_i = c and the circulatory stiffness Ω·K_i with K_i = −c·J, i.e.
// K_i(v, w) = c_t, K_i(w, v) = −c_t. The tilt vector (ry, rz) turns with the frame the
// same way, so K_i(ry, rz) = c_r, K_i(rz, ry) = −c_r.
#include <gtest/gtest.h>

#include <random>
#include <tuple>

#include <Eigen/Dense>

#include <feran/elements/rotating_damper.hpp>

namespace feran::test_rotating_damper {
namespace {

constexpr Index i_of(Dof d) { return static_cast<Index>(d); }

const RotatingDamperCoefficients coeffs{638.0, 0.57, 120.0, 0.05};  // c_t, c_r, c_x, c_rx

Real max_abs(const Matrix& a) { return a.cwiseAbs().maxCoeff(); }

// C_i symmetric positive semi-definite, K_i skew-symmetric, for both forms. The
// entries are copies of the coefficients, so symmetry is exact; the smallest
// eigenvalue of C_i may be a round-off negative of 1e-15·max c.
TEST(RotatingDamper, Structure) {
  for (const std::optional<Index> to : {std::optional<Index>{}, std::optional<Index>{3}}) {
    const LocalMatrices lm = RotatingDamper(1, to, coeffs).local_matrices({});
    const Index n = to ? 12 : 6;
    ASSERT_EQ(static_cast<Index>(lm.dofs.size()), n);
    ASSERT_EQ(lm.Ci.rows(), n);
    ASSERT_EQ(lm.Ki.rows(), n);
    EXPECT_EQ(max_abs(lm.Ci - lm.Ci.transpose()), 0.0);
    EXPECT_EQ(max_abs(lm.Ki + lm.Ki.transpose()), 0.0);
    const Vector ev = Eigen::SelfAdjointEigenSolver<Matrix>(lm.Ci).eigenvalues();
    EXPECT_GE(ev.minCoeff(), -1e-15 * coeffs.translational);
    // It adds no non-rotating terms.
    EXPECT_TRUE(lm.K.size() == 0 || lm.K.isZero(0.0));
    EXPECT_TRUE(lm.C.size() == 0 || lm.C.isZero(0.0));
    EXPECT_TRUE(lm.M.size() == 0 || lm.M.isZero(0.0));
  }
}

// Node to the rotating frame's axis: exact entries.
TEST(RotatingDamper, NodeToAxisEntries) {
  const LocalMatrices lm = RotatingDamper(0, std::nullopt, coeffs).local_matrices({});
  Matrix Ci = Matrix::Zero(6, 6), Ki = Matrix::Zero(6, 6);
  Ci.diagonal() << 120.0, 638.0, 638.0, 0.05, 0.57, 0.57;
  Ki(i_of(Dof::v), i_of(Dof::w)) = 638.0;
  Ki(i_of(Dof::w), i_of(Dof::v)) = -638.0;
  Ki(i_of(Dof::rz), i_of(Dof::ry)) = -0.57;
  Ki(i_of(Dof::ry), i_of(Dof::rz)) = 0.57;
  EXPECT_EQ(lm.Ci, Ci);
  EXPECT_EQ(lm.Ki, Ki);
}

// The inertial force −(C_i·q' + Ω·K_i·q) equals the rotating-frame damping force
// −c·(q' − Ω·J·q) transformed back, for random states. Tolerance 1e-13 relative
// (two products per entry).
TEST(RotatingDamper, ForceMatchesTheRotatingFrameLaw) {
  const LocalMatrices lm = RotatingDamper(0, std::nullopt, coeffs).local_matrices({});
  std::mt19937 gen(7);
  std::uniform_real_distribution<Real> dist(-1.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    Vector q(6), qd(6);
    for (Index k = 0; k < 6; ++k) {
      q(k) = dist(gen);
      qd(k) = dist(gen);
    }
    const Real W = 100.0 * (1.0 + dist(gen));
    const Vector f = -(lm.Ci * qd + W * lm.Ki * q);
    // J·(v, w) = (−w, v) and J·(ry, rz) = (−rz, ry); axial and torsion see no rotation.
    Vector expected(6);
    expected(i_of(Dof::u)) = -coeffs.axial * qd(i_of(Dof::u));
    expected(i_of(Dof::rx)) = -coeffs.torsional * qd(i_of(Dof::rx));
    expected(i_of(Dof::v)) = -coeffs.translational * (qd(i_of(Dof::v)) + W * q(i_of(Dof::w)));
    expected(i_of(Dof::w)) = -coeffs.translational * (qd(i_of(Dof::w)) - W * q(i_of(Dof::v)));
    expected(i_of(Dof::ry)) = -coeffs.rotational * (qd(i_of(Dof::ry)) + W * q(i_of(Dof::rz)));
    expected(i_of(Dof::rz)) = -coeffs.rotational * (qd(i_of(Dof::rz)) - W * q(i_of(Dof::ry)));
    for (Index k = 0; k < 6; ++k) EXPECT_NEAR(f(k), expected(k), 1e-13 * W * coeffs.translational) << "trial " << trial;
  }
}

// A rigid synchronous whirl r = R·e^{iΩt} (the orbit turning with the shaft) is at
// rest in the rotating frame, so the damper force vanishes: (iΩ·C_i + Ω·K_i)·Q = 0 for
// Q = (1, −i) on (v, w) (v = cos Ωt, w = sin Ωt) and likewise on the tilt (ry, rz).
// The backward whirl Q = (1, i) is damped with force 2Ω·c. Tolerance: exact cancel of
// two equal products, 1e-15 relative.
TEST(RotatingDamper, SynchronousForwardWhirlFeelsNoForce) {
  const LocalMatrices lm = RotatingDamper(0, std::nullopt, coeffs).local_matrices({});
  const Real W = 2 * pi * 33.4;
  const Complex i1(0, 1);
  const ComplexMatrix D = i1 * W * lm.Ci.cast<Complex>() + W * lm.Ki.cast<Complex>();
  for (const auto& [a, b, c] :
       {std::tuple{Dof::v, Dof::w, coeffs.translational}, std::tuple{Dof::ry, Dof::rz, coeffs.rotational}}) {
    ComplexVector fwd = ComplexVector::Zero(6), bwd = ComplexVector::Zero(6);
    fwd(i_of(a)) = 1.0;
    fwd(i_of(b)) = -i1;
    bwd(i_of(a)) = 1.0;
    bwd(i_of(b)) = i1;
    EXPECT_LE((D * fwd).cwiseAbs().maxCoeff(), 1e-15 * W * c);
    EXPECT_NEAR(std::abs((D * bwd)(i_of(a))), 2 * W * c, 1e-13 * W * c);
    EXPECT_NEAR(std::abs((D * bwd)(i_of(b))), 2 * W * c, 1e-13 * W * c);
  }
}

// Node to node: the damper acts on the relative motion only. Equal motion of both
// nodes gives no force; the node-a block is the node-to-axis matrix and the coupling
// blocks are its negative. Exact.
TEST(RotatingDamper, NodeToNodeActsOnRelativeMotion) {
  const LocalMatrices one = RotatingDamper(2, std::nullopt, coeffs).local_matrices({});
  const LocalMatrices two = RotatingDamper(2, 5, coeffs).local_matrices({});
  for (std::size_t d = 0; d < 6; ++d) {
    EXPECT_EQ(two.dofs[d], 12 + static_cast<Index>(d));
    EXPECT_EQ(two.dofs[d + 6], 30 + static_cast<Index>(d));
  }
  Matrix Ci(12, 12), Ki(12, 12);
  Ci << one.Ci, -one.Ci, -one.Ci, one.Ci;
  Ki << one.Ki, -one.Ki, -one.Ki, one.Ki;
  EXPECT_EQ(two.Ci, Ci);
  EXPECT_EQ(two.Ki, Ki);

  Vector q(12);
  q << 0.1, -0.2, 0.3, 0.4, -0.5, 0.6, 0.1, -0.2, 0.3, 0.4, -0.5, 0.6;
  // Equal motion of both nodes: no force, to round-off (FMA: see test_spring_damper).
  EXPECT_LE((two.Ci * q).norm(), 1e-14 * two.Ci.norm() * q.norm());
  EXPECT_LE((two.Ki * q).norm(), 1e-14 * two.Ki.norm() * q.norm());
  // Node b held still: node a feels the node-to-axis force.
  Vector qa = Vector::Zero(12);
  qa.head(6) = q.head(6);
  EXPECT_EQ(Vector((two.Ki * qa).head(6)), Vector(one.Ki * q.head(6)));
}

}  // namespace
}  // namespace feran::test_rotating_damper
