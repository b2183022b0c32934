#pragma once
// Small second-order systems with dense matrices for the integrator tests, the exact
// solution of their linear part, and helpers that measure convergence orders.
//
//   M x'' + D x' + K x = F cos(ω t) − k3·x³ − F_c·v/√(v² + ε²)   (component-wise x³, v)
//
// D and K may be non-symmetric (gyroscopic and circulatory terms), as in a rotor.

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include <feran/integrators/integrator.hpp>
#include <feran/integrators/rk3.hpp>
#include <feran/integrators/second_order_system.hpp>
#include <feran/core/types.hpp>

namespace feran::test {

class DenseSystem : public SecondOrderSystem {
 public:
  Matrix M, D, K;
  Vector F;             // forcing amplitude
  Real omega = 0.0;     // forcing frequency [rad/s]
  Real cubic = 0.0;     // k3 (Duffing)
  Real friction = 0.0;  // F_c
  Real eps = 1.0;       // ε of the regularised friction
  // The tangent set by set_jacobian is jacobian_scale·(K_T, D_T): 0.5 gives a poor
  // approximation, 0 gives T = 0 (the W-method becomes explicit).
  Real jacobian_scale = 1.0;
  // Reports its tangent exact (tangent_exact_at) when it is: the linear system with
  // jacobian_scale 1. Off by default, which makes the integrators confirm every step.
  bool report_exact_tangent = false;

  int n_rhs = 0;
  int n_jacobian = 0;
  int n_factor = 0;

  Index size() const override { return M.rows(); }

  void rhs(Real t, const Vector& x, const Vector& v, Vector& r) override {
    ++n_rhs;
    r = F * std::cos(omega * t) - D * v - K * x;
    for (Index i = 0; i < x.size(); ++i) {
      r(i) -= cubic * x(i) * x(i) * x(i);
      r(i) -= friction * v(i) / std::sqrt(v(i) * v(i) + eps * eps);
    }
  }
  void mass_times(const Vector& u, Vector& y) const override { y = M * u; }
  void solve_mass(const Vector& r, Vector& a) override {
    if (mass_lu_.rows() != M.rows()) mass_lu_.compute(M);  // M is set once per test
    a = mass_lu_.solve(r);
  }

  void set_jacobian(Real, const Vector& x, const Vector& v, bool exact) override {
    ++n_jacobian;
    K_T = K;
    D_T = D;
    if (exact) {
      for (Index i = 0; i < x.size(); ++i) {
        K_T(i, i) += 3.0 * cubic * x(i) * x(i);
        D_T(i, i) += friction * eps * eps / std::pow(v(i) * v(i) + eps * eps, 1.5);
      }
    }
    K_T *= jacobian_scale;
    D_T *= jacobian_scale;
  }
  void stiffness_times(const Vector& u, Vector& y) const override { y = K_T * u; }
  void damping_times(const Vector& u, Vector& y) const override { y = D_T * u; }
  bool factor_tangent(Real c_x, Real c_v, Real c_a) override {
    ++n_factor;
    const Matrix S = c_a * M + c_v * D_T + c_x * K_T;
    lu_.compute(S);
    return lu_.isInvertible();
  }
  void solve_tangent(const Vector& rhs, Vector& delta) override { delta = lu_.solve(rhs); }
  bool tangent_exact_at(Real) const override {
    return report_exact_tangent && cubic == 0.0 && friction == 0.0 && jacobian_scale == 1.0;
  }

  // sqrt of the ∞-norm of M⁻¹K: an upper bound of ω_max, exact for one DOF.
  Real highest_frequency() override { return std::sqrt(M.partialPivLu().solve(K).lpNorm<Eigen::Infinity>()); }

 private:
  Matrix K_T, D_T;
  Eigen::FullPivLU<Matrix> lu_;
  Eigen::PartialPivLU<Matrix> mass_lu_;
};

// Two DOF, non-symmetric: damping with a skew gyroscopic part, stiffness with a skew
// circulatory part; stable (all state eigenvalues have real part ≤ −0.064), forced.
inline DenseSystem gyroscopic_oscillator() {
  DenseSystem s;
  s.M = Matrix{{1.0, 0.0}, {0.0, 1.5}};
  s.D = Matrix{{0.3, 0.8}, {-0.8, 0.4}};
  s.K = Matrix{{4.0, 0.7}, {-0.3, 6.0}};
  s.F = Vector{{1.0, 0.5}};
  s.omega = 1.5;
  return s;
}

// The same with a Duffing term and a regularised dry friction (ε not small, so the
// solution is smooth and the orders are observable).
inline DenseSystem nonlinear_oscillator() {
  DenseSystem s = gyroscopic_oscillator();
  s.cubic = 2.0;
  s.friction = 0.5;
  s.eps = 0.2;
  return s;
}

// m x'' + k x = 0 with ω_n = omega_n.
inline DenseSystem undamped_sdof(Real omega_n) {
  DenseSystem s;
  s.M = Matrix::Constant(1, 1, 1.0);
  s.D = Matrix::Zero(1, 1);
  s.K = Matrix::Constant(1, 1, omega_n * omega_n);
  s.F = Vector::Zero(1);
  return s;
}

inline State initial_state(Index n) {
  State s;
  s.t = 0.0;
  s.x = Vector::LinSpaced(n, 0.1, -0.05);
  s.v = Vector::LinSpaced(n, 0.0, 0.2);
  return s;
}

// exp(A) by scaling and squaring of its Taylor series (accurate to a few ulps times
// the number of squarings for the small matrices here). Eigen's eigensolvers are
// avoided because g++ 12 warns (-Wmaybe-uninitialized) inside them.
inline Matrix expm(const Matrix& A) {
  const Real norm = A.cwiseAbs().colwise().sum().maxCoeff();
  int squarings = 0;
  while (norm / std::ldexp(1.0, squarings) > 0.5) ++squarings;
  const Matrix B = A / std::ldexp(1.0, squarings);
  Matrix term = Matrix::Identity(A.rows(), A.cols());
  Matrix sum = term;
  for (int k = 1; k <= 20; ++k) {
    term = term * B / static_cast<Real>(k);
    sum += term;
  }
  for (int k = 0; k < squarings; ++k) sum = sum * sum;
  return sum;
}

// Exact solution of the linear part: x = Re(X e^{iωt}) + the homogeneous part
// exp(A (t − t0))·z0 of the 2n×2n state matrix A.
class LinearExact {
 public:
  LinearExact(const DenseSystem& sys, const State& s0) : n_(sys.M.rows()), omega_(sys.omega), t0_(s0.t) {
    const Complex i(0.0, 1.0);
    const ComplexMatrix Z = (sys.K - omega_ * omega_ * sys.M).cast<Complex>() + i * omega_ * sys.D.cast<Complex>();
    X_ = Z.partialPivLu().solve(sys.F.cast<Complex>());
    A_ = Matrix::Zero(2 * n_, 2 * n_);
    A_.topRightCorner(n_, n_).setIdentity();
    A_.bottomLeftCorner(n_, n_) = -sys.M.partialPivLu().solve(sys.K);
    A_.bottomRightCorner(n_, n_) = -sys.M.partialPivLu().solve(sys.D);
    z0_.resize(2 * n_);
    const ComplexVector e = X_ * std::exp(i * omega_ * t0_);
    z0_.head(n_) = s0.x - e.real();
    z0_.tail(n_) = s0.v - (i * omega_ * e).real();
  }

  void at(Real t, Vector& x, Vector& v) const {
    const Complex i(0.0, 1.0);
    const Vector y = expm(A_ * (t - t0_)) * z0_;
    const ComplexVector e = X_ * std::exp(i * omega_ * t);
    x = y.head(n_) + e.real();
    v = y.tail(n_) + (i * omega_ * e).real();
  }

 private:
  Index n_;
  Real omega_;
  Real t0_;
  ComplexVector X_;
  Matrix A_;
  Vector z0_;
};

// Runs @p integ from @p s0 with @p n_steps equal steps to @p t_end; returns the final state
// (ok = false in @p report if any step failed).
inline State run_fixed(Integrator& integ, SecondOrderSystem& sys, State s, Real t_end, int n_steps,
                       StepReport* last = nullptr) {
  StepReport r = integ.start(sys, s);
  const Real dt = (t_end - s.t) / n_steps;
  for (int k = 0; k < n_steps && r.ok; ++k) r = integ.step(sys, s, dt);
  if (last) *last = r;
  return s;
}

inline Real state_error(const State& s, const Vector& x, const Vector& v) {
  return std::max((s.x - x).lpNorm<Eigen::Infinity>(), (s.v - v).lpNorm<Eigen::Infinity>());
}

// Final-state errors of runs with n0, 2·n0, …, 2^(levels−1)·n0 steps against (x_ref, v_ref);
// @p make returns a fresh integrator for each run.
template <class MakeIntegrator>
std::vector<Real> errors_at_halved_steps(MakeIntegrator make, SecondOrderSystem& sys, const State& s0, Real t_end,
                                         const Vector& x_ref, const Vector& v_ref, int n0 = 40, int levels = 6) {
  std::vector<Real> errors;
  for (int k = 0; k < levels; ++k) {
    auto integ = make();
    StepReport last;
    const State s = run_fixed(*integ, sys, s0, t_end, n0 << k, &last);
    errors.push_back(last.ok ? state_error(s, x_ref, v_ref) : std::numeric_limits<Real>::quiet_NaN());
  }
  return errors;
}

// errors_at_halved_steps on gyroscopic_oscillator() over [0, 5] s from initial_state(2),
// against its exact solution: the linear order test every integrator shares.
template <class MakeIntegrator>
std::vector<Real> linear_oscillator_errors(MakeIntegrator make) {
  DenseSystem sys = gyroscopic_oscillator();
  const State s0 = initial_state(2);
  Vector x, v;
  LinearExact(sys, s0).at(5.0, x, v);
  return errors_at_halved_steps(make, sys, s0, 5.0, x, v);
}

// Observed orders log2(e_k/e_{k+1}) of a sequence of errors at halved steps.
inline std::vector<Real> observed_orders(const std::vector<Real>& errors) {
  std::vector<Real> p;
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) p.push_back(std::log2(errors[k] / errors[k + 1]));
  return p;
}

// Reference solution of nonlinear_oscillator() at t_end = 4 s: Kutta's RK3 with 2^15
// steps. Its error, measured against 2^18 steps, is 2.5e-13: four orders below the
// finest errors the tests measure against it (1.3e-9).
inline State nonlinear_reference(const State& s0) {
  DenseSystem sys = nonlinear_oscillator();
  Rk3 rk3{IntegratorSettings{}};
  return run_fixed(rk3, sys, s0, 4.0, 1 << 15);
}

}  // namespace feran::test
