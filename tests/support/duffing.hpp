#pragma once
// Duffing's oscillator m x'' + c x' + k x + k₃x³ = F cos ωt, shared by the periodic
// tests: the dense system for harmonic balance, and the closed form of its
// single-harmonic frequency response [(k − mω²)A + ¾k₃A³]² + (cωA)² = F², and the
// oscillator as a rotor model.

#include <cmath>
#include <vector>

#include <feran/analyses/periodic/harmonic_balance.hpp>
#include <feran/analyses/periodic/orbits.hpp>

#include "test_models.hpp"

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

// A cubic spring −k₃x³ on one DOF, written as a nonlinear force.
struct CubicSpring {
  Index dof = 0;
  Real k3 = 0.0;
  std::string_view kind() const { return "cubic_spring"; }
  std::vector<Index> nodes() const { return {dof / dofs_per_node}; }
  std::vector<Index> dofs() const { return {dof}; }
  NonlinearForceValue force(const MotionState&, const Vector& x, const Vector&) const {
    return {Vector::Constant(1, -k3 * x(0) * x(0) * x(0)), Matrix::Constant(1, 1, -3 * k3 * x(0) * x(0)), Matrix()};
  }
};

// The oscillator as a rotor: a point mass on a spring and damper moving in y alone, the
// cubic spring a force, F a synchronous harmonic force (Ω = ω).
inline Model rotor_model() {
  Model model = test::jeffcott(m, k, c, 0.0);
  test::fix(model, 0, {Dof::w});
  model.forces.emplace_back(CubicSpring{global_dof(0, Dof::v), k3}, "cubic");
  model.forces.emplace_back(HarmonicForce{.node = 0,
                                          .type = HarmonicForce::Kind::fixed,
                                          .direction = Dof::v,
                                          .amplitude = F,
                                          .phase = 0.0,
                                          .frequency = std::nullopt,
                                          .time_table = {}},
                            "F");
  return model;
}

// The rotor model condensed: its one coordinate, y, and the unbalance-like force.
inline CondensedRotor condense(const Model& model) {
  return CondensedRotor(model, nullptr,
                        {.modes = 12,
                         .gravity = Eigen::Vector3d::Zero(),
                         .static_loads = false,
                         .unbalance = true,
                         .reference_speed = 0.0});
}

// Its branches' settings: one harmonic on 8 samples, Ω from 0.5 to 2.5, lengths of
// order 1, at most 2000 points, the corrector's tolerance 1e-10.
inline OrbitSettings branch_settings() {
  OrbitSettings settings;
  settings.fourier = {.harmonics = 1, .samples = 8};
  settings.length_scale = 1.0;
  settings.continuation.p_min = 0.5;
  settings.continuation.p_max = 2.5;
  settings.continuation.max_points = 2000;
  settings.continuation.tolerance = 1e-10;
  return settings;
}

// The amplitudes A of the single-harmonic orbits at ω (one or three), increasing: the
// sign changes of the response curve − F² on a fine grid, each refined by bisection
// to 1e-14.
inline std::vector<Real> orbit_amplitudes(Real w) {
  std::vector<Real> out;
  const auto g = [&](Real A) { return response_curve(w, A) - F * F; };
  for (Real A = 1e-4; A < 5.0; A += 1e-3) {
    Real lo = A, hi = A + 1e-3;
    if (g(lo) * g(hi) > 0) continue;
    for (int i = 0; i < 100 && hi - lo > 1e-14; ++i) {
      const Real mid = 0.5 * (lo + hi);
      (g(lo) * g(mid) <= 0 ? hi : lo) = mid;
    }
    out.push_back(0.5 * (lo + hi));
  }
  return out;
}

}  // namespace feran::test::duffing
