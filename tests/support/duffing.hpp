#pragma once
// Duffing's oscillator m x'' + c x' + k x + k₃x³ = F cos ωt, shared by the periodic
// tests: the dense system for harmonic balance, and the closed form of its
// single-harmonic frequency response [(k − mω²)A + ¾k₃A³]² + (cωA)² = F².

#include <cmath>
#include <vector>

#include <feran/analyses/periodic/harmonic_balance.hpp>

namespace feran::test::duffing {

inline constexpr Real m = 1.0, c = 0.05, k = 1.0, k3 = 0.5, F = 0.2;

// The system with the force F cos ωt (harmonic 1's cosine).
inline PeriodicSystem system(const FourierBasis& basis) {
  PeriodicSystem s{.M = Matrix::Constant(1, 1, m),
                   .C = Matrix::Constant(1, 1, c),
                   .K = Matrix::Constant(1, 1, k),
                   .external = Vector::Zero(basis.terms()),
                   .force = [](Real, const Vector& x, const Vector&) {
                     return NonlinearForceValue{Vector::Constant(1, -k3 * x(0) * x(0) * x(0)),
                                                Matrix::Constant(1, 1, -3 * k3 * x(0) * x(0)), Matrix()};
                   }};
  s.external(1) = F;
  return s;
}

// [(k − mω²)A + ¾k₃A³]² + (cωA)², equal to F² on the single-harmonic response.
inline Real response_curve(Real w, Real A) {
  return std::pow((k - m * w * w) * A + 0.75 * k3 * A * A * A, 2) + std::pow(c * w * A, 2);
}

// The discriminant of the cubic in u = A² whose roots are the orbits at ω.
inline Real discriminant(Real w) {
  const Real k0 = k - m * w * w, q = 0.75 * k3;
  const Real a = q * q, b = 2 * k0 * q, cc = k0 * k0 + c * c * w * w, d = -F * F;
  return 18 * a * b * cc * d - 4 * b * b * b * d + b * b * cc * cc - 4 * a * cc * cc * cc - 27 * a * a * d * d;
}

// The folds of the single-harmonic response in [0.5, 2.5]: where the discriminant
// vanishes, by scanning and bisection to 1e-14.
inline std::vector<Real> closed_form_folds() {
  std::vector<Real> folds;
  for (Real w = 0.5; w < 2.5; w += 1e-3) {
    Real lo = w, hi = w + 1e-3;
    if (discriminant(lo) * discriminant(hi) > 0) continue;
    for (int i = 0; i < 100 && hi - lo > 1e-14; ++i) {
      const Real mid = 0.5 * (lo + hi);
      (discriminant(lo) * discriminant(mid) <= 0 ? hi : lo) = mid;
    }
    folds.push_back(0.5 * (lo + hi));
  }
  return folds;
}

}  // namespace feran::test::duffing
