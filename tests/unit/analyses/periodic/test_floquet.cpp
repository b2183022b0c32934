// Floquet multipliers of periodic orbits (analyses/periodic/floquet.hpp):
// - a linear time-invariant system's exponents are its eigenvalues, each once, in the
//   strip |Im s| ≤ ω/2 when its frequencies lie there: Hill's method keeps exactly
//   those among the copies s + ikω (to 1e-10 of |s|);
// - Duffing's forced oscillator between its folds has three orbits; Hill's multipliers
//   and those of the monodromy matrix integrated over one period (Runge–Kutta, 4000
//   steps: error ≈ 1e-12) agree to 1e-9 (measured 8e-12: H = 9 harmonics resolve these
//   orbits to about that; the margin allows other platforms' rounding), the lower and upper orbits are
//   stable, and the middle one has one real multiplier above 1 (a saddle, as the fold
//   that joins it to the others says it must). The exponential integrator's monodromy
//   agrees with the Runge–Kutta one (1e-8 at 400 steps) and is of order four.
// - Mathieu's equation x'' + c x' + (δ + ε cos ωt)x = 0 about x = 0 (a force with the
//   time dependence, at ω = 1): near δ = ¼ the first tongue of parametric resonance,
//   where a real multiplier passes −1 — period doubling. Hill's multipliers (H = 12)
//   against the monodromy's (2000 steps; 1e-9), one below −1 inside the tongue (δ = 0.25) and
//   none outside it (δ = 0.4), and the edges of the tongue found by bisection on the
//   multiplier −1 against the monodromy's edges (1e-8). Without the rule for exponents
//   on the strip's edge (floquet.cpp) Hill kept the stable multiplier twice inside the
//   tongue and called the unstable trivial solution stable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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

// Duffing's three orbits at ω = 1.5 (H = 9, 40 samples), lower, middle and upper, each
// solved from its single-harmonic approximation: the roots A of
// [(k − mω²)A + ¾k₃A³]² + (cωA)² = F², found by scanning for sign changes, and their
// a = Fκ/(κ² + c²ω²), b = Fcω/(κ² + c²ω²), κ = k − mω² + ¾k₃A². Those the balance
// does not converge from are left out.
constexpr Real three_orbits_frequency = 1.5;
std::vector<Vector> three_orbits(const FourierBasis& basis, const PeriodicSystem& s) {
  const Real w = three_orbits_frequency;
  const auto g = [&](Real A) { return response_curve(w, A) - F * F; };
  std::vector<Vector> orbits;
  for (Real A = 1e-3; A < 3.0; A += 1e-3)
    if (g(A) * g(A + 1e-3) < 0) {
      const Real kappa = k - m * w * w + 0.75 * k3 * A * A, d = kappa * kappa + c * c * w * w;
      Vector X0 = Vector::Zero(basis.terms());
      X0(1) = F * kappa / d;
      X0(2) = F * c * w / d;
      const BalanceResult r = solve_balance(basis, s, w, X0);
      if (r.converged) orbits.push_back(r.X);
    }
  return orbits;
}

TEST(Floquet, DuffingsThreeOrbitsByHillAndByMonodromy) {
  const FourierBasis basis{.harmonics = 9, .samples = 40};
  const PeriodicSystem s = duffing(basis);
  const Real w = three_orbits_frequency;
  const std::vector<Vector> orbits = three_orbits(basis, s);
  ASSERT_EQ(orbits.size(), 3U);
  std::vector<Real> amplitudes, largest;
  for (const Vector& X : orbits) {  // lower, middle and upper orbit
    const Floquet hill = hill_floquet(basis, s, w, balance_terms(basis, s, w, X, true), false);
    const Floquet mono = monodromy_floquet(basis, s, w, X, 4000, false);
    ASSERT_EQ(hill.multipliers.size(), 2);
    const Real size = std::hypot(X(1), X(2));
    const std::vector<Complex> a = sorted(hill.multipliers), b = sorted(mono.multipliers);
    for (std::size_t j = 0; j < a.size(); ++j) EXPECT_LT(std::abs(a[j] - b[j]), 1e-9) << size << " " << j;
    amplitudes.push_back(size);
    largest.push_back(hill.largest);
  }
  ASSERT_LT(amplitudes[0], amplitudes[1]);
  ASSERT_LT(amplitudes[1], amplitudes[2]);  // three distinct orbits
  EXPECT_LT(largest[0], 1.0);
  EXPECT_GT(largest[1], 1.0 + 1e-3);
  EXPECT_LT(largest[2], 1.0);
}

// The exponential integrator's monodromy on Duffing's three orbits: the multipliers
// of the Runge–Kutta monodromy (4000 steps, error ≈ 1e-12) to 1e-8 at 400 steps
// (measured 2.3e-9 on the middle orbit), and its fourth order: from 20 to 40 steps the
// error falls by at least 12 (measured 15.8–16.0).
TEST(Floquet, ExponentialMonodromyIsOfFourthOrderOnDuffingsOrbits) {
  const FourierBasis basis{.harmonics = 9, .samples = 40};
  const PeriodicSystem s = duffing(basis);
  const Real w = three_orbits_frequency;
  const std::vector<Vector> orbits = three_orbits(basis, s);
  ASSERT_EQ(orbits.size(), 3U);
  for (const Vector& X : orbits) {
    const std::vector<Complex> reference = sorted(monodromy_floquet(basis, s, w, X, 4000, false).multipliers);
    const auto error = [&](Index steps) {
      const std::vector<Complex> mu =
          sorted(monodromy_floquet(basis, s, w, X, steps, false, MonodromyScheme::exponential).multipliers);
      Real e = 0.0;
      for (std::size_t j = 0; j < mu.size(); ++j) e = std::max(e, std::abs(mu[j] - reference[j]));
      return e;
    };
    const Real size = std::hypot(X(1), X(2));
    std::printf("orbit %.4f: errors %.3g (20 steps), %.3g (40), %.3g (400)\n", size, error(20), error(40), error(400));
    EXPECT_LT(error(400), 1e-8) << size;
    EXPECT_GT(error(20) / error(40), 12.0) << size;
  }
}

PeriodicSystem mathieu(Real delta, Real eps, Real damping) {
  return PeriodicSystem{
      .M = Matrix::Identity(1, 1),
      .C = Matrix::Constant(1, 1, damping),
      .K = Matrix::Constant(1, 1, delta),
      .external = {},
      .force = [eps](Real t, const Vector& x, const Vector&) {
        const Real e = eps * std::cos(t);  // t = θ/ω with ω = 1
        return NonlinearForceValue{Vector::Constant(1, -e * x(0)), Matrix::Constant(1, 1, -e), Matrix()};
      }};
}

// The most negative real multiplier, or +∞ when there is none.
Real most_negative(const Floquet& f) {
  Real most = std::numeric_limits<Real>::infinity();
  for (Index j = 0; j < f.multipliers.size(); ++j)
    if (std::abs(f.multipliers(j).imag()) < 1e-9 && f.multipliers(j).real() < 0)
      most = std::min(most, f.multipliers(j).real());
  return most;
}

TEST(Floquet, MathieusTongueIsAPeriodDoubling) {
  const FourierBasis basis{.harmonics = 12, .samples = 64};
  const Real eps = 0.2, damping = 0.02;
  const Vector X = Vector::Zero(basis.terms());
  const auto hill = [&](Real delta) {
    const PeriodicSystem s = mathieu(delta, eps, damping);
    return hill_floquet(basis, s, 1.0, balance_terms(basis, s, 1.0, X, true), false);
  };
  const auto mono = [&](Real delta) {
    return monodromy_floquet(basis, mathieu(delta, eps, damping), 1.0, X, 2000, false);
  };
  for (const Real delta : {0.25, 0.4}) {
    const std::vector<Complex> a = sorted(hill(delta).multipliers), b = sorted(mono(delta).multipliers);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t j = 0; j < a.size(); ++j) EXPECT_LT(std::abs(a[j] - b[j]), 1e-9) << delta << " " << j;
  }
  EXPECT_LT(most_negative(hill(0.25)), -1.0);  // inside the tongue: a multiplier beyond −1
  EXPECT_GT(hill(0.4).largest, 0.0);
  EXPECT_LT(hill(0.4).largest, 1.0);  // outside: stable
  // The tongue's edges: where the most negative multiplier is −1, by bisection.
  const auto edge = [&](auto floquet, Real inside, Real outside) {
    for (int i = 0; i < 45; ++i) {
      const Real mid = 0.5 * (inside + outside);
      (most_negative(floquet(mid)) < -1.0 ? inside : outside) = mid;
    }
    return 0.5 * (inside + outside);
  };
  for (const Real outside : {0.1, 0.4}) {
    const Real by_hill = edge(hill, 0.25, outside), by_monodromy = edge(mono, 0.25, outside);
    EXPECT_NEAR(by_hill, by_monodromy, 1e-8) << outside;
    EXPECT_NEAR(by_hill, 0.25, 0.6 * eps) << outside;  // about ¼ ∓ ε/2, to first order in ε
  }
}

}  // namespace
}  // namespace feran::test_floquet
