// Harmonic balance of a dense system (analyses/periodic/harmonic_balance.hpp) against
// closed forms:
// - a linear system's balance is its dynamic stiffness: the orbit under F cos ωt is
//   X = F/(k − mω² + icω) in one step (to 1e-12);
// - Duffing's oscillator m x'' + c x' + k x + k₃x³ = F cos ωt with one harmonic: every
//   orbit found satisfies the single-harmonic frequency response
//   [(k − mω²)A + (3/4)k₃A³]² + (cωA)² = F² (to 1e-10, the Newton tolerance), and in the
//   range between the folds the lower and upper branches are both found, from starts
//   near each;
// - adding harmonics converges: the fundamental's amplitude changes by less and less
//   (H = 1, 3, 5, 7 against H = 11; each step at least ten times smaller here).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <feran/analyses/periodic/harmonic_balance.hpp>
#include <feran/core/error.hpp>

#include "duffing.hpp"

namespace feran::test_harmonic_balance {
namespace {

using namespace test::duffing;  // NOLINT(google-build-using-namespace): the shared case's names

PeriodicSystem duffing(const FourierBasis& basis) { return test::duffing::system(basis); }

Real amplitude(const Vector& X) { return std::hypot(X(1), X(2)); }

TEST(HarmonicBalance, LinearSystemIsItsDynamicStiffness) {
  const FourierBasis basis{.harmonics = 2, .samples = 8};
  PeriodicSystem s = duffing(basis);
  s.force = nullptr;
  const Real w = 0.8;
  const BalanceResult r = solve_balance(basis, s, w, Vector::Zero(basis.terms()));
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  const Complex X = F / Complex(k - m * w * w, c * w);  // x = Re(X e^{iωt}) = a cos + b sin, a = Re X, b = −Im X
  EXPECT_NEAR(r.X(1), X.real(), 1e-12 * std::abs(X));
  EXPECT_NEAR(r.X(2), -X.imag(), 1e-12 * std::abs(X));
  EXPECT_NEAR(r.X(3), 0.0, 1e-15);
}

TEST(HarmonicBalance, DuffingMeetsTheSingleHarmonicResponseOnBothBranches) {
  const FourierBasis basis{.harmonics = 1, .samples = 8};
  const PeriodicSystem s = duffing(basis);
  const Real w = 1.5;  // between the folds for these values
  std::vector<Real> found;
  for (const Real start : {0.0, 2.2}) {
    Vector X0 = Vector::Zero(basis.terms());
    X0(1) = start;
    const BalanceResult r = solve_balance(basis, s, w, X0);
    ASSERT_TRUE(r.converged) << start;
    const Real A = amplitude(r.X);
    EXPECT_NEAR(response_curve(w, A), F * F, 1e-10 * F * F) << start;
    found.push_back(A);
  }
  EXPECT_LT(found[0], 0.5);  // the lower branch
  EXPECT_GT(found[1], 1.5);  // the upper branch
}

TEST(HarmonicBalance, AddingHarmonicsConverges) {
  const Real w = 1.2;
  auto fundamental = [&](Index H) {
    const FourierBasis basis{.harmonics = H, .samples = 4 * H + 4};
    Vector X0 = Vector::Zero(basis.terms());
    X0(1) = 1.5;
    const BalanceResult r = solve_balance(basis, duffing(basis), w, X0);
    EXPECT_TRUE(r.converged) << H;
    return amplitude(r.X);
  };
  const Real reference = fundamental(11);
  Real previous = std::abs(fundamental(1) - reference);
  EXPECT_GT(previous, 0.0);
  for (const Index H : {3, 5, 7}) {
    const Real error = std::abs(fundamental(H) - reference);
    EXPECT_LT(error, 0.1 * previous) << H;
    previous = error;
  }
}

// The truncation estimate: with one harmonic, x³ along A cos(ωt + φ) has (3/4)A³ at ω
// and (1/4)A³ at 3ω, so the estimate is 1/3 whatever the orbit (to 1e-12); with more
// harmonics it falls as the fundamental's error does.
TEST(HarmonicBalance, TruncationEstimateSaysWhenToAddHarmonics) {
  const Real w = 1.2;
  Real previous = 0.0;
  for (const Index H : {1, 3, 5, 7}) {
    const FourierBasis basis{.harmonics = H, .samples = 4 * H + 4};
    Vector X0 = Vector::Zero(basis.terms());
    X0(1) = 1.5;
    const BalanceResult r = solve_balance(basis, duffing(basis), w, X0);
    ASSERT_TRUE(r.converged) << H;
    if (H == 1) {
      EXPECT_NEAR(r.truncation, 1.0 / 3.0, 1e-12);
    } else {
      EXPECT_LT(r.truncation, 0.1 * previous) << H;
    }
    previous = r.truncation;
  }
}

// A force on some DOFs only (PeriodicSystem::force_dofs) is the same force written on
// all of them: the residual and Jacobian agree to rounding (1e-14 of their size), and
// ∂R/∂ω equals central differences (step 1e-6, O(h²) error; tolerance 1e-7).
TEST(HarmonicBalance, ForceOnSomeDofsIsTheForceOnAll) {
  const FourierBasis basis{.harmonics = 3, .samples = 16};
  const Real w = 1.3;
  PeriodicSystem on_one{.M = Matrix::Identity(2, 2),
                        .C = (Matrix(2, 2) << 0.1, -0.02, -0.02, 0.05).finished(),
                        .K = (Matrix(2, 2) << 2.0, -1.0, -1.0, 1.5).finished(),
                        .external = Vector::Zero(2 * basis.terms()),
                        .force =
                            [](Real, const Vector& x, const Vector& v) {
                              return NonlinearForceValue{Vector::Constant(1, -k3 * x(0) * x(0) * x(0) - 0.2 * v(0)),
                                                         Matrix::Constant(1, 1, -3 * k3 * x(0) * x(0)),
                                                         Matrix::Constant(1, 1, -0.2)};
                            },
                        .force_dofs = {1}};
  on_one.external(2) = F;
  PeriodicSystem on_all = on_one;
  on_all.force_dofs.clear();
  on_all.force = [](Real, const Vector& x, const Vector& v) {
    NonlinearForceValue f{Vector::Zero(2), Matrix::Zero(2, 2), Matrix::Zero(2, 2)};
    f.f(1) = -k3 * x(1) * x(1) * x(1) - 0.2 * v(1);
    f.dfdx(1, 1) = -3 * k3 * x(1) * x(1);
    f.dfdv(1, 1) = -0.2;
    return f;
  };
  Vector X(2 * basis.terms());
  for (Index i = 0; i < X.size(); ++i) X(i) = 0.4 * std::sin(1.3 * static_cast<Real>(i) + 0.2);
  const BalanceTerms a = balance_terms(basis, on_one, w, X, true), b = balance_terms(basis, on_all, w, X, true);
  EXPECT_LT((a.R - b.R).norm(), 1e-14 * b.R.norm());
  EXPECT_LT((balance_residual(basis, on_one, w, X) - a.R).norm(), 1e-14 * a.R.norm());
  EXPECT_LT((balance_residual(basis, on_all, w, X) - a.R).norm(), 1e-14 * a.R.norm());
  EXPECT_LT((a.dR_dX - b.dR_dX).norm(), 1e-14 * b.dR_dX.norm());
  EXPECT_LT((a.Jv - b.Jv).norm(), 1e-14 * b.Jv.norm());
  EXPECT_LT((a.dR_domega - b.dR_domega).norm(), 1e-14 * b.dR_domega.norm());
  const Real h = 1e-6;
  const Vector d = (balance_terms(basis, on_one, w + h, X).R - balance_terms(basis, on_one, w - h, X).R) / (2 * h);
  EXPECT_LT((a.dR_domega - d).cwiseAbs().maxCoeff(), 1e-7 * (1 + d.cwiseAbs().maxCoeff()));
}

TEST(HarmonicBalance, RefusesMismatchedSizes) {
  const FourierBasis basis{.harmonics = 1, .samples = 8};
  EXPECT_THROW(solve_balance(basis, duffing(basis), 1.0, Vector::Zero(5)), Error);
}

}  // namespace
}  // namespace feran::test_harmonic_balance
