#include <feran/analyses/periodic/harmonic_balance.hpp>

#include <algorithm>

#include <Eigen/LU>
#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

Matrix linear_balance(const FourierBasis& basis, const PeriodicSystem& system, Real omega) {
  basis.check();
  const Index n = system.K.rows();
  if (system.K.cols() != n || system.M.rows() != n || system.M.cols() != n || system.C.rows() != n ||
      system.C.cols() != n)
    throw Error(fmt::format("harmonic balance: M, C and K must be square and of one size ({} DOFs)", n));
  const Index terms = basis.terms();
  Matrix L = Matrix::Zero(n * terms, n * terms);
  L.block(0, 0, n, n) = system.K;
  for (Index k = 1; k <= basis.harmonics; ++k) {
    const Real kw = static_cast<Real>(k) * omega;
    const Matrix direct = system.K - kw * kw * system.M;
    const Index a = (2 * k - 1) * n, b = 2 * k * n;
    L.block(a, a, n, n) = direct;
    L.block(a, b, n, n) = kw * system.C;
    L.block(b, b, n, n) = direct;
    L.block(b, a, n, n) = -kw * system.C;
  }
  return L;
}

namespace {

struct Residual {
  Vector R;
  Matrix J;
  Real scale = 0.0;
};

Residual residual(const FourierBasis& basis, const PeriodicSystem& system, const Matrix& L, Real omega,
                  const Vector& X) {
  Residual r{.R = L * X, .J = L, .scale = 0.0};
  r.scale = r.R.norm();
  if (system.external.size() != 0) {
    r.R -= system.external;
    r.scale = std::max(r.scale, system.external.norm());
  }
  if (system.force) {
    const AftResult f = aft(basis, omega, X, system.force);
    r.R -= f.F;
    r.J -= f.J;
    r.scale = std::max(r.scale, f.F.norm());
  }
  return r;
}

Real relative(const Residual& r) { return r.scale > 0 ? r.R.norm() / r.scale : r.R.norm(); }

// The force's harmonics H + 1 … 3H relative to 0 … H, by an AFT on three times the
// harmonics (the orbit's coefficients padded with zeros; a cubic force's reach), with
// samples enough that force harmonics up to 9H do not fold onto them.
Real truncation(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X) {
  if (!system.force || basis.harmonics == 0) return 0.0;
  const Index n = X.size() / basis.terms();
  const FourierBasis wide{.harmonics = 3 * basis.harmonics,
                          .samples = std::max(basis.samples, 12 * basis.harmonics + 1)};
  Vector padded = Vector::Zero(n * wide.terms());
  padded.head(X.size()) = X;
  const Vector F = aft(wide, omega, padded, system.force).F;
  const Real kept = F.head(X.size()).norm(), left = F.tail(F.size() - X.size()).norm();
  return kept > 0 ? left / kept : 0.0;
}

}  // namespace

BalanceResult solve_balance(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X0,
                            const BalanceSettings& settings) {
  const Matrix L = linear_balance(basis, system, omega);
  if (X0.size() != L.rows())
    throw Error(fmt::format("harmonic balance: the start has {} coefficients, the system {}", X0.size(), L.rows()));
  if (system.external.size() != 0 && system.external.size() != L.rows())
    throw Error(fmt::format("harmonic balance: the external force has {} coefficients, the system {}",
                            system.external.size(), L.rows()));
  BalanceResult out{.X = X0, .converged = false, .iterations = 0, .residual = 0.0, .truncation = 0.0, .jacobian = {}};
  Residual r = residual(basis, system, L, omega, out.X);
  out.residual = relative(r);
  while (out.residual > settings.tolerance && out.iterations < settings.max_iterations) {
    const Eigen::PartialPivLU<Matrix> lu(r.J);
    const Vector step = lu.solve(r.R);
    if (!step.allFinite()) break;  // a singular Jacobian: the last iterate is kept
    ++out.iterations;
    // Halve the step until the residual falls (a fold or a poor start overshoots).
    Real t = 1.0;
    for (int halving = 0; halving <= 20; ++halving, t *= 0.5) {
      const Vector trial = out.X - t * step;
      Residual next = residual(basis, system, L, omega, trial);
      if (next.R.norm() < r.R.norm() || halving == 20) {
        out.X = trial;
        r = std::move(next);
        break;
      }
    }
    out.residual = relative(r);
  }
  out.converged = out.residual <= settings.tolerance;
  out.truncation = truncation(basis, system, omega, out.X);
  out.jacobian = std::move(r.J);
  return out;
}

}  // namespace feran
