// The alternating frequency–time step (analyses/periodic/aft.hpp) against closed forms:
// - a linear force −K x − C v is balanced harmonic by harmonic exactly:
//   F_ak = −K a_k − kωC b_k, F_bk = −K b_k + kωC a_k (to 1e-12 of the largest term);
// - a cubic spring −k₃x³ along x = A cos ωt has the coefficients −(3/4)k₃A³ at ω and
//   −(1/4)k₃A³ at 3ω, nothing else, when N samples resolve harmonic 3 without aliasing
//   (to 1e-13); with too few samples the third harmonic aliases onto the first, by the
//   amount the DFT predicts;
// - the Jacobian of a nonlinear force of positions and velocities on two DOFs equals
//   central differences of the coefficients (step 1e-6: their error is O(h²) ≈ 1e-12
//   against rounding ≈ 1e-10 relative; tolerance 1e-7), and so does ∂F/∂ω;
// - the velocity Jacobian Jv (Hill's method) makes up the whole Jacobian of a force of
//   velocities alone: J = ω·Jv·∇ (to 1e-13 of the largest entry).
#include <gtest/gtest.h>

#include <cmath>

#include <feran/analyses/periodic/aft.hpp>
#include <feran/core/error.hpp>

namespace feran::test_aft {
namespace {

TEST(Aft, LinearForceIsBalancedHarmonicByHarmonic) {
  const FourierBasis basis{.harmonics = 3, .samples = 16};
  const Real omega = 7.0;
  Matrix K(2, 2), C(2, 2);
  K << 3.0, -1.0, 0.5, 2.0;
  C << 0.2, 0.05, -0.1, 0.3;
  const Vector X = Vector::LinSpaced(2 * basis.terms(), -1.0, 2.0);
  const AftResult r = aft(basis, omega, X, [&](Real, const Vector& x, const Vector& v) {
    return NonlinearForceValue{-K * x - C * v, -K, -C};
  });
  Vector expected(X.size());
  expected.segment(0, 2) = -K * X.segment(0, 2);
  for (Index k = 1; k <= basis.harmonics; ++k) {
    const Vector a = X.segment((2 * k - 1) * 2, 2), b = X.segment(2 * k * 2, 2);
    const Real kw = static_cast<Real>(k) * omega;
    expected.segment((2 * k - 1) * 2, 2) = -K * a - kw * C * b;
    expected.segment(2 * k * 2, 2) = -K * b + kw * C * a;
  }
  EXPECT_LT((r.F - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  // The Jacobian of a linear force is its own balance: F = J·X.
  EXPECT_LT((r.J * X - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

TEST(Aft, CubicSpringHasItsFirstAndThirdHarmonics) {
  const Real k3 = 2.5e4, A = 0.3, omega = 11.0;
  const auto cubic = [&](Real, const Vector& x, const Vector&) {
    return NonlinearForceValue{Vector::Constant(1, -k3 * x(0) * x(0) * x(0)),
                               Matrix::Constant(1, 1, -3 * k3 * x(0) * x(0)), Matrix()};
  };
  const FourierBasis basis{.harmonics = 3, .samples = 8};  // harmonic 3 ≤ N − H − 1 = 4
  Vector X = Vector::Zero(basis.terms());
  X(1) = A;  // a₁
  const AftResult r = aft(basis, omega, X, cubic);
  Vector expected = Vector::Zero(basis.terms());
  expected(1) = -0.75 * k3 * A * A * A;
  expected(5) = -0.25 * k3 * A * A * A;
  EXPECT_LT((r.F - expected).cwiseAbs().maxCoeff(), 1e-13 * k3 * A * A * A);
  // With H = 1 and N = 4 samples, harmonic 3 aliases onto N − 3 = 1: a₁ = −k₃A³.
  const FourierBasis coarse{.harmonics = 1, .samples = 4};
  Vector X1 = Vector::Zero(coarse.terms());
  X1(1) = A;
  EXPECT_NEAR(aft(coarse, omega, X1, cubic).F(1), -k3 * A * A * A, 1e-12 * k3 * A * A * A);
  // N = 5 resolves it: the single-harmonic balance's −(3/4)k₃A³.
  const FourierBasis enough{.harmonics = 1, .samples = 5};
  EXPECT_NEAR(aft(enough, omega, X1, cubic).F(1), -0.75 * k3 * A * A * A, 1e-12 * k3 * A * A * A);
}

TEST(Aft, JacobianEqualsDifferencesOfTheCoefficients) {
  const FourierBasis basis{.harmonics = 2, .samples = 12};
  const Real omega = 3.0;
  // f₀ = −x₀³ − 0.4·x₁·v₀² − 0.1 sin ωt,  f₁ = −x₀x₁ − 0.3·v₁³.
  const auto force = [&](Real t, const Vector& x, const Vector& v) {
    NonlinearForceValue f{Vector(2), Matrix::Zero(2, 2), Matrix::Zero(2, 2)};
    f.f(0) = -x(0) * x(0) * x(0) - 0.4 * x(1) * v(0) * v(0) - 0.1 * std::sin(omega * t);
    f.f(1) = -x(0) * x(1) - 0.3 * v(1) * v(1) * v(1);
    f.dfdx << -3 * x(0) * x(0), -0.4 * v(0) * v(0), -x(1), -x(0);
    f.dfdv << -0.8 * x(1) * v(0), 0.0, 0.0, -0.9 * v(1) * v(1);
    return f;
  };
  Vector X(2 * basis.terms());
  for (Index i = 0; i < X.size(); ++i) X(i) = 0.3 * std::sin(1.7 * static_cast<Real>(i) + 0.4);
  const AftResult r = aft(basis, omega, X, force);
  const Real h = 1e-6;
  for (Index i = 0; i < X.size(); ++i) {
    Vector p = X, m = X;
    p(i) += h;
    m(i) -= h;
    const Vector d = (aft(basis, omega, p, force).F - aft(basis, omega, m, force).F) / (2 * h);
    EXPECT_LT((r.J.col(i) - d).cwiseAbs().maxCoeff(), 1e-7 * (1 + d.cwiseAbs().maxCoeff())) << i;
  }
  // ∂F/∂ω holds the phase θ = ωt fixed: the forcing term, written −0.1 sin θ, does not
  // change with ω.
  const auto at_phase = [&](Real w) {
    return [&, w](Real t, const Vector& x, const Vector& v) { return force(w * t / omega, x, v); };
  };
  EXPECT_LT((force_coefficients(basis, omega, X, force) - r.F).norm(), 1e-15 * r.F.norm());
  const Vector dw =
      (aft(basis, omega + h, X, at_phase(omega + h)).F - aft(basis, omega - h, X, at_phase(omega - h)).F) / (2 * h);
  EXPECT_LT((r.dF_domega - dw).cwiseAbs().maxCoeff(), 1e-7 * (1 + dw.cwiseAbs().maxCoeff()));
}

TEST(Aft, VelocityJacobianMakesUpAForceOfVelocities) {
  const FourierBasis basis{.harmonics = 3, .samples = 16};
  const Real omega = 2.5;
  const auto force = [](Real, const Vector&, const Vector& v) {
    NonlinearForceValue f{Vector(2), Matrix::Zero(2, 2), Matrix::Zero(2, 2)};
    f.f << -0.8 * v(0) * v(1), -0.3 * v(1) * v(1) * v(1);
    f.dfdv << -0.8 * v(1), -0.8 * v(0), 0.0, -0.9 * v(1) * v(1);
    return f;
  };
  Vector X(2 * basis.terms());
  for (Index i = 0; i < X.size(); ++i) X(i) = 0.2 * std::cos(0.9 * static_cast<Real>(i) + 0.1);
  const AftResult r = aft(basis, omega, X, force, true);
  ASSERT_EQ(r.Jv.rows(), X.size());
  Matrix D(X.size(), X.size());  // ∇ column by column
  for (Index i = 0; i < X.size(); ++i) D.col(i) = phase_derivative(basis, Vector::Unit(X.size(), i));
  const Matrix J = omega * r.Jv * D;
  EXPECT_LT((r.J - J).cwiseAbs().maxCoeff(), 1e-13 * r.J.cwiseAbs().maxCoeff());
}

TEST(Aft, MotionAtIsTheFourierSeries) {
  const FourierBasis basis{.harmonics = 2, .samples = 8};
  const Real omega = 5.0, t = 0.37;
  Vector X(basis.terms());
  X << 0.1, 0.2, -0.3, 0.05, 0.07;
  Vector x, v;
  motion_at(basis, omega, X, t, x, v);
  const Real w = omega * t;
  EXPECT_NEAR(x(0), 0.1 + 0.2 * std::cos(w) - 0.3 * std::sin(w) + 0.05 * std::cos(2 * w) + 0.07 * std::sin(2 * w),
              1e-15);
  EXPECT_NEAR(v(0), omega * (-0.2 * std::sin(w) - 0.3 * std::cos(w) - 0.1 * std::sin(2 * w) + 0.14 * std::cos(2 * w)),
              1e-14);
}

TEST(Aft, RefusesWhatItCannotResolve) {
  const auto zero = [](Real, const Vector& x, const Vector&) {
    return NonlinearForceValue{Vector::Zero(x.size()), Matrix::Zero(x.size(), x.size()), Matrix()};
  };
  EXPECT_THROW(aft({.harmonics = 3, .samples = 6}, 1.0, Vector::Zero(7), zero), Error);
  EXPECT_THROW(aft({.harmonics = 1, .samples = 4}, 1.0, Vector::Zero(4), zero), Error);
  EXPECT_THROW(aft({.harmonics = 1, .samples = 4}, 0.0, Vector::Zero(3), zero), Error);
}

}  // namespace
}  // namespace feran::test_aft
