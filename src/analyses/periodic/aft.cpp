#include <feran/analyses/periodic/aft.hpp>

#include <cmath>

#include <fmt/format.h>

#include <feran/core/error.hpp>

namespace feran {

void FourierBasis::check() const {
  if (harmonics < 0)
    throw Error(fmt::format("harmonic balance: the number of harmonics must be at least 0, got {}", harmonics));
  if (samples < terms())
    throw Error(fmt::format("harmonic balance: {} time samples cannot resolve {} harmonics: at least 2H + 1 = {}",
                            samples, harmonics, terms()));
}

namespace {

// The row of the basis functions at phase θ: [1, cos θ, sin θ, …, cos Hθ, sin Hθ], and
// their derivatives with respect to θ.
void basis_row(Index H, Real theta, Vector& g, Vector& dg) {
  g.resize(2 * H + 1);
  dg.resize(2 * H + 1);
  g(0) = 1.0;
  dg(0) = 0.0;
  // cos kθ and sin kθ by the angle-addition recurrence from cos θ and sin θ (one
  // sincos per row instead of H; its rounding grows like k·ε, below 1e-14 here).
  const Real c1 = std::cos(theta), s1 = std::sin(theta);
  Real c = 1.0, s = 0.0;
  for (Index k = 1; k <= H; ++k) {
    const Real next_c = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = next_c;
    g(2 * k - 1) = c;
    g(2 * k) = s;
    dg(2 * k - 1) = -static_cast<Real>(k) * s;
    dg(2 * k) = static_cast<Real>(k) * c;
  }
}

Index dofs_of(const FourierBasis& basis, const Vector& X) {
  const Index terms = basis.terms();
  if (X.size() == 0 || X.size() % terms != 0)
    throw Error(fmt::format("harmonic balance: {} coefficients are not a whole number of DOFs with {} terms each",
                            X.size(), terms));
  return X.size() / terms;
}

// x = Σ_m g_m X_m over the terms m, each X_m a block of n values.
void combine(const Vector& X, const Vector& g, Index n, Vector& x) {
  x.setZero(n);
  for (Index m = 0; m < g.size(); ++m) x += g(m) * X.segment(m * n, n);
}

// The motion at sample j of N: its phase θ_j, the basis row there and x, ẋ.
Real sample(const FourierBasis& basis, Real omega, const Vector& X, Index n, Index j, Vector& g, Vector& dg, Vector& x,
            Vector& v) {
  const Real theta = 2 * pi * static_cast<Real>(j) / static_cast<Real>(basis.samples);
  basis_row(basis.harmonics, theta, g, dg);
  combine(X, g, n, x);
  combine(X, dg, n, v);
  v *= omega;
  return theta;
}

}  // namespace

void motion_at(const FourierBasis& basis, Real omega, const Vector& X, Real t, Vector& x, Vector& v) {
  basis.check();
  const Index n = dofs_of(basis, X);
  Vector g, dg;
  basis_row(basis.harmonics, omega * t, g, dg);
  combine(X, g, n, x);
  combine(X, dg, n, v);
  v *= omega;
}

Vector phase_derivative(const FourierBasis& basis, const Vector& X) {
  const Index n = dofs_of(basis, X);
  Vector D = Vector::Zero(X.size());
  for (Index k = 1; k <= basis.harmonics; ++k) {
    const Real kr = static_cast<Real>(k);
    D.segment((2 * k - 1) * n, n) = kr * X.segment(2 * k * n, n);
    D.segment(2 * k * n, n) = -kr * X.segment((2 * k - 1) * n, n);
  }
  return D;
}

Vector force_coefficients(const FourierBasis& basis, Real omega, const Vector& X, const LocalForce& force) {
  basis.check();
  if (!(omega > 0)) throw Error("harmonic balance: the base frequency must be positive");
  const Index n = dofs_of(basis, X), terms = basis.terms(), N = basis.samples;
  Vector F = Vector::Zero(n * terms), g, dg, x, v;
  for (Index j = 0; j < N; ++j) {
    const Real theta = sample(basis, omega, X, n, j, g, dg, x, v);
    const Vector f = force(theta / omega, x, v).f;
    for (Index c = 0; c < terms; ++c) F.segment(c * n, n) += (c == 0 ? 1.0 : 2.0) / static_cast<Real>(N) * g(c) * f;
  }
  return F;
}

AftResult aft(const FourierBasis& basis, Real omega, const Vector& X, const LocalForce& force, bool velocity_jacobian) {
  basis.check();
  if (!(omega > 0)) throw Error("harmonic balance: the base frequency must be positive");
  const Index n = dofs_of(basis, X), terms = basis.terms(), N = basis.samples;
  AftResult out{.F = Vector::Zero(n * terms),
                .J = Matrix::Zero(n * terms, n * terms),
                .dF_domega = Vector::Zero(n * terms),
                .Jv = velocity_jacobian ? Matrix::Zero(n * terms, n * terms) : Matrix()};
  Vector g, dg, x, v, w(terms), dv;
  Matrix local(n, n * terms);   // ∂f_j/∂X at one sample
  Matrix localv(n, n * terms);  // ∂f_j/∂V at one sample
  for (Index j = 0; j < N; ++j) {
    const Real theta = sample(basis, omega, X, n, j, g, dg, x, v);
    const NonlinearForceValue f = force(theta / omega, x, v);
    // The DFT's weights: 1/N for the mean, 2/N for the cosines and sines.
    w = (2.0 / static_cast<Real>(N)) * g;
    w(0) = 1.0 / static_cast<Real>(N);
    const bool has_v = f.dfdv.size() != 0;
    for (Index m = 0; m < terms; ++m) {
      local.middleCols(m * n, n) = g(m) * f.dfdx;
      if (has_v) local.middleCols(m * n, n) += (omega * dg(m)) * f.dfdv;
      if (velocity_jacobian) {
        if (has_v)
          localv.middleCols(m * n, n) = g(m) * f.dfdv;
        else
          localv.middleCols(m * n, n).setZero();
      }
    }
    if (has_v) dv.noalias() = f.dfdv * (v / omega);  // ∂f/∂ẋ · ∂ẋ/∂ω
    for (Index c = 0; c < terms; ++c) {
      out.F.segment(c * n, n) += w(c) * f.f;
      out.J.middleRows(c * n, n) += w(c) * local;
      if (has_v) out.dF_domega.segment(c * n, n) += w(c) * dv;
      if (velocity_jacobian) out.Jv.middleRows(c * n, n) += w(c) * localv;
    }
  }
  return out;
}

}  // namespace feran
