#include <feran/analyses/periodic/harmonic_balance.hpp>

#include <algorithm>
#include <vector>

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

void check_sizes(const FourierBasis& basis, const PeriodicSystem& system, const Vector& X) {
  const Index rows = system.K.rows() * basis.terms();
  if (X.size() != rows)
    throw Error(fmt::format("harmonic balance: the orbit has {} coefficients, the system {}", X.size(), rows));
  if (system.external.size() != 0 && system.external.size() != rows)
    throw Error(fmt::format("harmonic balance: the external force has {} coefficients, the system {}",
                            system.external.size(), rows));
  for (const Index d : system.force_dofs)
    if (d < 0 || d >= system.K.rows())
      throw Error(fmt::format("harmonic balance: the force acts on DOF {}, the system has {}", d, system.K.rows()));
}

// The AFT of the system's force on its DOFs, scattered into the whole layout.
AftResult force_terms(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X,
                      bool velocity_jacobian) {
  if (system.force_dofs.empty()) return aft(basis, omega, X, system.force, velocity_jacobian);
  const Index n = system.K.rows(), nl = static_cast<Index>(system.force_dofs.size()), terms = basis.terms();
  std::vector<Index> at;  // position in X of each local coefficient
  at.reserve(static_cast<std::size_t>(nl * terms));
  for (Index m = 0; m < terms; ++m)
    for (const Index d : system.force_dofs) at.push_back(m * n + d);
  Vector Xl(nl * terms);
  for (std::size_t i = 0; i < at.size(); ++i) Xl(static_cast<Index>(i)) = X(at[i]);
  const AftResult local = aft(basis, omega, Xl, system.force, velocity_jacobian);
  AftResult out{.F = Vector::Zero(X.size()),
                .J = Matrix::Zero(X.size(), X.size()),
                .dF_domega = Vector::Zero(X.size()),
                .Jv = velocity_jacobian ? Matrix::Zero(X.size(), X.size()) : Matrix()};
  for (std::size_t i = 0; i < at.size(); ++i) {
    const Index li = static_cast<Index>(i);
    out.F(at[i]) = local.F(li);
    out.dF_domega(at[i]) = local.dF_domega(li);
    for (std::size_t j = 0; j < at.size(); ++j) {
      out.J(at[i], at[j]) = local.J(li, static_cast<Index>(j));
      if (velocity_jacobian) out.Jv(at[i], at[j]) = local.Jv(li, static_cast<Index>(j));
    }
  }
  return out;
}

// (∂L/∂ω)·X: harmonic k's −2k²ωM a_k + kC b_k and −2k²ωM b_k − kC a_k.
Vector linear_frequency_derivative(const FourierBasis& basis, const PeriodicSystem& system, Real omega,
                                   const Vector& X) {
  const Index n = system.K.rows();
  Vector d = Vector::Zero(X.size());
  for (Index k = 1; k <= basis.harmonics; ++k) {
    const Real kr = static_cast<Real>(k);
    const auto a = X.segment((2 * k - 1) * n, n), b = X.segment(2 * k * n, n);
    d.segment((2 * k - 1) * n, n) = -2 * kr * kr * omega * (system.M * a) + kr * (system.C * b);
    d.segment(2 * k * n, n) = -2 * kr * kr * omega * (system.M * b) - kr * (system.C * a);
  }
  return d;
}

}  // namespace

BalanceTerms balance_terms(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X,
                           bool velocity_jacobian) {
  const Matrix L = linear_balance(basis, system, omega);
  check_sizes(basis, system, X);
  BalanceTerms t{.R = L * X,
                 .dR_dX = L,
                 .dR_domega = linear_frequency_derivative(basis, system, omega, X),
                 .Jv = {},
                 .scale = 0.0};
  t.scale = t.R.norm();
  if (system.external.size() != 0) {
    t.R -= system.external;
    t.scale = std::max(t.scale, system.external.norm());
  }
  if (system.force) {
    AftResult f = force_terms(basis, system, omega, X, velocity_jacobian);
    t.R -= f.F;
    t.dR_dX -= f.J;
    t.dR_domega -= f.dF_domega;
    t.scale = std::max(t.scale, f.F.norm());
    t.Jv = std::move(f.Jv);
  } else if (velocity_jacobian) {
    t.Jv = Matrix::Zero(X.size(), X.size());
  }
  return t;
}

namespace {

// The force's coefficients alone (no Jacobians) on the whole layout.
Vector force_vector(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X) {
  if (system.force_dofs.empty()) return force_coefficients(basis, omega, X, system.force);
  const Index n = system.K.rows(), nl = static_cast<Index>(system.force_dofs.size()), terms = basis.terms();
  Vector Xl(nl * terms);
  for (Index m = 0; m < terms; ++m)
    for (Index d = 0; d < nl; ++d) Xl(m * nl + d) = X(m * n + system.force_dofs[static_cast<std::size_t>(d)]);
  const Vector Fl = force_coefficients(basis, omega, Xl, system.force);
  Vector F = Vector::Zero(X.size());
  for (Index m = 0; m < terms; ++m)
    for (Index d = 0; d < nl; ++d) F(m * n + system.force_dofs[static_cast<std::size_t>(d)]) = Fl(m * nl + d);
  return F;
}

}  // namespace

Vector balance_residual(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X) {
  check_sizes(basis, system, X);
  Vector R = linear_balance(basis, system, omega) * X;
  if (system.external.size() != 0) R -= system.external;
  if (system.force) R -= force_vector(basis, system, omega, X);
  return R;
}

Real truncation_estimate(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X) {
  if (!system.force || basis.harmonics == 0) return 0.0;
  check_sizes(basis, system, X);
  const Index n = X.size() / basis.terms();
  const FourierBasis wide{.harmonics = 3 * basis.harmonics,
                          .samples = std::max(basis.samples, 12 * basis.harmonics + 1)};
  Vector padded = Vector::Zero(n * wide.terms());
  padded.head(X.size()) = X;
  const Vector F = force_vector(wide, system, omega, padded);
  const Real kept = F.head(X.size()).norm(), left = F.tail(F.size() - X.size()).norm();
  return kept > 0 ? left / kept : 0.0;
}

namespace {

Real relative(const BalanceTerms& r) { return r.scale > 0 ? r.R.norm() / r.scale : r.R.norm(); }

}  // namespace

BalanceResult solve_balance(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X0,
                            const BalanceSettings& settings) {
  BalanceResult out{.X = X0, .converged = false, .iterations = 0, .residual = 0.0, .truncation = 0.0, .jacobian = {}};
  BalanceTerms r = balance_terms(basis, system, omega, out.X);
  out.residual = relative(r);
  while (out.residual > settings.tolerance && out.iterations < settings.max_iterations) {
    const Eigen::PartialPivLU<Matrix> lu(r.dR_dX);
    const Vector step = lu.solve(r.R);
    if (!step.allFinite()) break;  // a singular Jacobian: the last iterate is kept
    ++out.iterations;
    // Halve the step until the residual falls (a fold or a poor start overshoots).
    Real t = 1.0;
    for (int halving = 0; halving <= 20; ++halving, t *= 0.5) {
      const Vector trial = out.X - t * step;
      BalanceTerms next = balance_terms(basis, system, omega, trial);
      if (next.R.norm() < r.R.norm() || halving == 20) {
        out.X = trial;
        r = std::move(next);
        break;
      }
    }
    out.residual = relative(r);
  }
  out.converged = out.residual <= settings.tolerance;
  out.truncation = truncation_estimate(basis, system, omega, out.X);
  out.jacobian = std::move(r.dR_dX);
  return out;
}

}  // namespace feran
