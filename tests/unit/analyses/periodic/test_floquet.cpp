// Floquet multipliers of periodic orbits (analyses/periodic/floquet.hpp):
// - a linear time-invariant system's exponents are its eigenvalues, each once, in the
//   strip |Im s| ≤ ω/2 when its frequencies lie there: Hill's method keeps exactly
//   those among the copies s + ikω (to 1e-10 of |s|);
// - Duffing's forced oscillator between its folds has three orbits; Hill's multipliers
//   and those of the monodromy matrix integrated over one period (Runge–Kutta, 4000
//   steps: error ≈ 1e-12) agree to 1e-9 (measured 8e-12: H = 9 harmonics resolve these
//   orbits to about that; the margin allows other platforms' rounding), the lower and upper orbits are
//   stable, and the middle one has one real multiplier above 1 (a saddle, as the fold
//   that joins it to the others says it must).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include <feran/analyses/periodic/floquet.hpp>
#include <feran/core/error.hpp>

#include "duffing.hpp"

namespace feran::test_floquet {
namespace {

using namespace test::duffing;  // NOLINT(google-build-using-namespace): the shared case's names

PeriodicSystem duffing(const FourierBasis& basis) { return test::duffing::system(basis); }

std::vector<Complex> sorted(const ComplexVector& v) {
  std::vector<Complex> out(v.data(), v.data() + v.size());
  std::sort(out.begin(), out.end(),
            [](Complex a, Complex b) { return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag(); });
  return out;
}

TEST(Floquet, LinearSystemsExponentsAreItsEigenvalues) {
  const FourierBasis basis{.harmonics = 4, .samples = 16};
  const Matrix M = (Matrix(2, 2) << 2.0, 0.0, 0.0, 1.0).finished();
  const Matrix C = (Matrix(2, 2) << 0.3, 0.5, -0.5, 0.1).finished();  // a gyroscopic part
  const Matrix K = (Matrix(2, 2) << 3.0, -1.0, -1.0, 2.0).finished();
  const PeriodicSystem s{.M = M, .C = C, .K = K, .external = {}, .force = nullptr};
  const Real w = 5.0;  // the system's frequencies are below 2.5 rad/s
  const Vector X = Vector::Zero(2 * basis.terms());
  const Floquet f = hill_floquet(basis, s, w, balance_terms(basis, s, w, X, true), false);
  Matrix A = Matrix::Zero(4, 4);
  A.topRightCorner(2, 2).setIdentity();
  A.bottomLeftCorner(2, 2) = -M.inverse() * K;
  A.bottomRightCorner(2, 2) = -M.inverse() * C;
  const ComplexVector ev = Eigen::EigenSolver<Matrix>(A).eigenvalues();
  const std::vector<Complex> a = sorted(f.exponents), b = sorted(ev);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t j = 0; j < a.size(); ++j) EXPECT_LT(std::abs(a[j] - b[j]), 1e-10 * std::abs(b[j])) << j;
  // The monodromy of a linear system gives e^{sT}.
  const Floquet g = monodromy_floquet(basis, s, w, X, 400, false);
  EXPECT_NEAR(g.largest, f.largest, 1e-9);
}

TEST(Floquet, DuffingsThreeOrbitsByHillAndByMonodromy) {
  const FourierBasis basis{.harmonics = 9, .samples = 40};
  const PeriodicSystem s = duffing(basis);
  const Real w = 1.5;
  // The three single-harmonic orbits as starts: the roots A of
  // [(k − mω²)A + ¾k₃A³]² + (cωA)² = F², found by scanning for sign changes, and their
  // a = Fκ/(κ² + c²ω²), b = Fcω/(κ² + c²ω²), κ = k − mω² + ¾k₃A².
  const auto g = [&](Real A) { return response_curve(w, A) - F * F; };
  std::vector<Vector> starts;
  for (Real A = 1e-3; A < 3.0; A += 1e-3)
    if (g(A) * g(A + 1e-3) < 0) {
      const Real kappa = k - m * w * w + 0.75 * k3 * A * A, d = kappa * kappa + c * c * w * w;
      Vector X0 = Vector::Zero(basis.terms());
      X0(1) = F * kappa / d;
      X0(2) = F * c * w / d;
      starts.push_back(X0);
    }
  ASSERT_EQ(starts.size(), 3U);
  std::vector<Real> amplitudes, largest;
  for (const Vector& X0 : starts) {  // lower, middle and upper orbit
    const Real start = std::hypot(X0(1), X0(2));
    const BalanceResult r = solve_balance(basis, s, w, X0);
    ASSERT_TRUE(r.converged) << start;
    const Floquet hill = hill_floquet(basis, s, w, balance_terms(basis, s, w, r.X, true), false);
    const Floquet mono = monodromy_floquet(basis, s, w, r.X, 4000, false);
    ASSERT_EQ(hill.multipliers.size(), 2);
    const std::vector<Complex> a = sorted(hill.multipliers), b = sorted(mono.multipliers);
    for (std::size_t j = 0; j < a.size(); ++j) EXPECT_LT(std::abs(a[j] - b[j]), 1e-9) << start << " " << j;
    amplitudes.push_back(std::hypot(r.X(1), r.X(2)));
    largest.push_back(hill.largest);
  }
  ASSERT_LT(amplitudes[0], amplitudes[1]);
  ASSERT_LT(amplitudes[1], amplitudes[2]);  // three distinct orbits
  EXPECT_LT(largest[0], 1.0);
  EXPECT_GT(largest[1], 1.0 + 1e-3);
  EXPECT_LT(largest[2], 1.0);
}

}  // namespace
}  // namespace feran::test_floquet
