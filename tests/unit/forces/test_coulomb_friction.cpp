#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <feran/forces/coulomb_friction.hpp>

namespace feran::test_coulomb_friction {
namespace {

CoulombFriction data(bool two_nodes) {
  CoulombFriction d;
  d.node_a = 0;
  if (two_nodes) d.node_b = 1;
  d.force_amplitude = 5.2;
  d.moment_amplitude = 0.3;
  d.epsilon_t = 1e-3;
  d.epsilon_r = 1e-2;
  return d;
}

// Jacobian blocks against central finite differences at random states. Step 1e-6 of
// the regularisation scale: truncation ~1e-12, round-off ~1e-10 of the entries.
TEST(CoulombFriction, JacobianMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-1e-3, 1e-3);
  for (bool two : {false, true}) {
    const CoulombFriction f = data(two);
    const Index n = static_cast<Index>(f.dofs().size());
    const MotionState s{0.0, 150.0};
    for (int trial = 0; trial < 10; ++trial) {
      Vector x(n), v(n);
      for (Index i = 0; i < n; ++i) x(i) = u(rng), v(i) = 0.1 * u(rng);
      const NonlinearForceValue base = f.force(s, x, v);
      for (Index j = 0; j < n; ++j) {
        const Real h = 1e-9;
        Vector xp = x, xm = x, vp = v, vm = v;
        xp(j) += h, xm(j) -= h, vp(j) += h, vm(j) -= h;
        const Vector dfx = (f.force(s, xp, v).f - f.force(s, xm, v).f) / (2 * h);
        const Vector dfv = (f.force(s, x, vp).f - f.force(s, x, vm).f) / (2 * h);
        for (Index i = 0; i < n; ++i) {
          EXPECT_NEAR(base.dfdx(i, j), dfx(i), 1e-5 * (1 + std::abs(dfx(i))));
          EXPECT_NEAR(base.dfdv(i, j), dfv(i), 1e-5 * (1 + std::abs(dfv(i))));
        }
      }
    }
  }
}

// Far from zero relative velocity the force has magnitude F_c0 and opposes the
// rotating-frame velocity s = ṙ − jΩr: for a node at rest at r = (a, 0) with Ω > 0,
// s = (0, −Ωa), so F points along +z with magnitude F_c0 (to 1e-8: ε/|s| ≈ 1e-4,
// the regularisation reduces the magnitude by ½(ε/|s|)²).
TEST(CoulombFriction, OpposesTheRotatingFrameVelocity) {
  const CoulombFriction f = data(false);
  Vector x = Vector::Zero(4), v = Vector::Zero(4);
  x(0) = 0.1;  // v = 0.1 m
  const NonlinearForceValue r = f.force({0.0, 100.0}, x, v);
  EXPECT_NEAR(r.f(0), 0.0, 1e-12);
  EXPECT_NEAR(r.f(1), 5.2, 1e-6);
}

// A whirl synchronous with the shaft (the shaft frame sees no motion) meets no
// friction: r = R e^{jΩt} gives ṙ = jΩr, s = 0.
TEST(CoulombFriction, NoForceOnASynchronousWhirl) {
  const CoulombFriction f = data(false);
  const Real W = 80.0, R = 2e-3;
  Vector x = Vector::Zero(4), v = Vector::Zero(4);
  x(0) = R;          // v
  v(1) = W * R;      // ẇ: the point moves from +y towards +z at speed ΩR
  x(3) = 1e-3;       // rz
  v(2) = -W * 1e-3;  // tilt pair (rz, −ry) turns with the shaft: −ṙy = Ω·rz
  const NonlinearForceValue r = f.force({0.0, W}, x, v);
  EXPECT_LT(r.f.norm(), 1e-12);
}

TEST(CoulombFriction, ActsOnTheRelativeMotionOfTwoNodes) {
  const CoulombFriction f = data(true);
  Vector x = Vector::Zero(8), v = Vector::Zero(8);
  v(0) = v(4) = 0.3;  // both nodes move together: no relative motion
  EXPECT_LT(f.force({0.0, 10.0}, x, v).f.norm(), 1e-12);
  v(4) = 0.0;
  const NonlinearForceValue r = f.force({0.0, 0.0}, x, v);
  EXPECT_NEAR(r.f(0), -5.2, 1e-4);  // ε/|s| = 3e-3: magnitude within 5e-6 relative
  EXPECT_NEAR(r.f(4), 5.2, 1e-4);   // reaction on node b
}

}  // namespace
}  // namespace feran::test_coulomb_friction
