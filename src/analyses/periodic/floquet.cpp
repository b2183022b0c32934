#include <feran/analyses/periodic/floquet.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <unsupported/Eigen/MatrixFunctions>
#include <fmt/format.h>

#include <feran/core/error.hpp>

extern "C" {
// LAPACK: eigenvalues and right eigenvectors of a real general matrix.
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr, double* wi,
            double* vl, const int* ldvl, double* vr, const int* ldvr, double* work, const int* lwork, int* info);
}

namespace feran {

namespace {

struct RealEigen {
  Vector wr, wi;
  Matrix vr;  // dgeev's layout: a complex pair as columns j (real) and j + 1 (imaginary)
};

RealEigen real_eigen(Matrix A) {
  const int N = static_cast<int>(A.rows());
  RealEigen e{.wr = Vector(N), .wi = Vector(N), .vr = Matrix(N, N)};
  double vl_dummy = 0.0, work_query = 0.0;
  const int one = 1;
  int info = 0, lwork = -1;
  dgeev_("N", "V", &N, A.data(), &N, e.wr.data(), e.wi.data(), &vl_dummy, &one, e.vr.data(), &N, &work_query, &lwork,
         &info);
  lwork = static_cast<int>(work_query);
  Vector work(lwork);
  dgeev_("N", "V", &N, A.data(), &N, e.wr.data(), e.wi.data(), &vl_dummy, &one, e.vr.data(), &N, work.data(), &lwork,
         &info);
  if (info != 0)
    throw Error(
        fmt::format("Floquet analysis: the eigenvalues of Hill's matrix were not found (LAPACK dgeev info {})", info));
  return e;
}

// The mean harmonic k̄ = Σ k|P_k|² / Σ |P_k|² of a perturbation whose real-basis
// coefficients are @p P (n per term): P_{±k} = (a_k ∓ i b_k)/2.
Real centroid(const ComplexVector& P, Index n, Index H) {
  Real num = 0.0, den = P.head(n).squaredNorm();
  for (Index k = 1; k <= H; ++k) {
    const ComplexVector a = P.segment((2 * k - 1) * n, n), b = P.segment(2 * k * n, n);
    const Real plus = 0.25 * (a - Complex(0, 1) * b).squaredNorm(),
               minus = 0.25 * (a + Complex(0, 1) * b).squaredNorm();
    num += static_cast<Real>(k) * (plus - minus);
    den += plus + minus;
  }
  return den > 0 ? num / den : 0.0;
}

// The multipliers from the exponents, the phase's multiplier (@p trivial; −1: none,
// or the one nearest 1 when @p autonomous and no index is given), the largest.
void finish(Floquet& out, Real omega, bool autonomous, Index trivial = -1) {
  const Real T = 2 * pi / omega;
  const Index m = out.exponents.size();
  out.multipliers.resize(m);
  for (Index j = 0; j < m; ++j) out.multipliers(j) = std::exp(out.exponents(j) * T);
  out.trivial = -1;
  if (autonomous && trivial >= 0) {
    out.trivial = trivial;
  } else if (autonomous && m > 0) {
    Index best = 0;
    for (Index j = 1; j < m; ++j)
      if (std::abs(out.multipliers(j) - 1.0) < std::abs(out.multipliers(best) - 1.0)) best = j;
    out.trivial = best;
  }
  out.largest = 0.0;
  for (Index j = 0; j < m; ++j)
    if (j != out.trivial) out.largest = std::max(out.largest, std::abs(out.multipliers(j)));
}

}  // namespace

Floquet hill_floquet(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const BalanceTerms& terms,
                     bool autonomous) {
  const Index n = system.M.rows(), T = basis.terms(), N = n * T, H = basis.harmonics;
  if (terms.dR_dX.rows() != N || terms.Jv.rows() != N)
    throw Error("Floquet analysis: Hill's method needs the balance's Jacobians with the velocity part (∂F/∂V)");
  // C̃ = I ⊗ C + 2ω(∇ ⊗ M) − ∂F/∂V; ∇ maps (a_k, b_k) to (k b_k, −k a_k).
  Matrix Ct = -terms.Jv;
  for (Index m = 0; m < T; ++m) Ct.block(m * n, m * n, n, n) += system.C;
  for (Index k = 1; k <= H; ++k) {
    const Real w2k = 2 * omega * static_cast<Real>(k);
    const Index a = (2 * k - 1) * n, b = 2 * k * n;
    Ct.block(a, b, n, n) += w2k * system.M;
    Ct.block(b, a, n, n) -= w2k * system.M;
  }
  const Eigen::PartialPivLU<Matrix> mass(system.M);
  Matrix A = Matrix::Zero(2 * N, 2 * N);
  A.topRightCorner(N, N).setIdentity();
  for (Index m = 0; m < T; ++m) {
    A.block(N + m * n, 0, n, N) = -mass.solve(terms.dR_dX.middleRows(m * n, n));
    A.block(N + m * n, N, n, N) = -mass.solve(Ct.middleRows(m * n, n));
  }
  const RealEigen e = real_eigen(std::move(A));
  // Every eigenvalue with its centroid; a complex pair's members have opposite ones.
  std::vector<Complex> values(static_cast<std::size_t>(2 * N));
  std::vector<Real> centre(static_cast<std::size_t>(2 * N));
  for (Index j = 0; j < 2 * N; ++j) {
    const auto u = static_cast<std::size_t>(j);
    values[u] = Complex(e.wr(j), e.wi(j));
    if (e.wi(j) == 0.0) {
      centre[u] = centroid(e.vr.col(j).head(N).cast<Complex>(), n, H);
    } else if (e.wi(j) > 0.0) {
      const ComplexVector P =
          e.vr.col(j).head(N).cast<Complex>() + Complex(0, 1) * e.vr.col(j + 1).head(N).cast<Complex>();
      centre[u] = centroid(P, n, H);
      centre[u + 1] = -centre[u];
      values[u + 1] = std::conj(values[u]);
      ++j;
    }
  }
  // The exponents whose eigenvectors are centred (|k̄| < ½) among those the harmonics
  // resolve (Re s ≥ −Hω/2) first, by |k̄|; then the strongly damped ones, whose copies
  // s + ikω the truncated matrix cannot tell apart (it mixes them, some into real
  // values whose vectors look centred); then the rest. Which copy of a strongly damped
  // exponent is kept does not change its multiplier's modulus, ≈ e^{−πH}.
  const Real resolved = -0.5 * static_cast<Real>(std::max<Index>(H, 1)) * omega;
  // An exponent on the strip's edge (Im s = ±ω/2: a real negative multiplier, period
  // doubling) is one exponent, though both s and its conjugate s − iω lie on the edge
  // with |k̄| = ½: the one with Im s > 0 is kept, the other goes last.
  const auto on_lower_edge = [&](std::size_t j) { return std::abs(values[j].imag() + 0.5 * omega) <= 1e-7 * omega; };
  const auto group = [&](std::size_t j) {
    if (on_lower_edge(j)) return 3;
    if (values[j].real() < resolved) return 1;
    return std::abs(centre[j]) < 0.5 ? 0 : 2;
  };
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const int ga = group(a), gb = group(b);
    if (ga != gb) return ga < gb;
    return std::abs(centre[a]) < std::abs(centre[b]);
  });
  Floquet out;
  out.exponents.resize(2 * n);
  for (Index j = 0; j < 2 * n; ++j) out.exponents(j) = values[order[static_cast<std::size_t>(j)]];
  finish(out, omega, autonomous);
  return out;
}

namespace {

// The force's Jacobians on all n DOFs at phase time t along the orbit.
void jacobians_at(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X, Real t,
                  Matrix& Jx, Matrix& Jv) {
  const Index n = system.M.rows();
  Jx.setZero(n, n);
  Jv.setZero(n, n);
  if (!system.force) return;
  Vector x, v;
  motion_at(basis, omega, X, t, x, v);
  if (system.force_dofs.empty()) {
    const NonlinearForceValue f = system.force(t, x, v);
    Jx = f.dfdx;
    if (f.dfdv.size() != 0) Jv = f.dfdv;
    return;
  }
  const auto nl = static_cast<Index>(system.force_dofs.size());
  Vector xl(nl), vl(nl);
  for (Index i = 0; i < nl; ++i) {
    xl(i) = x(system.force_dofs[static_cast<std::size_t>(i)]);
    vl(i) = v(system.force_dofs[static_cast<std::size_t>(i)]);
  }
  const NonlinearForceValue f = system.force(t, xl, vl);
  for (Index i = 0; i < nl; ++i)
    for (Index j = 0; j < nl; ++j) {
      const Index r = system.force_dofs[static_cast<std::size_t>(i)],
                  c = system.force_dofs[static_cast<std::size_t>(j)];
      Jx(r, c) += f.dfdx(i, j);
      if (f.dfdv.size() != 0) Jv(r, c) += f.dfdv(i, j);
    }
}

// The state matrix A(t) of ż = A(t)z, z = (δx, δẋ), along the orbit.
class StateMatrix {
 public:
  StateMatrix(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X)
      : basis_(basis), system_(system), omega_(omega), X_(X), mass_(system.M) {
    const Index n = system.M.rows();
    base_ = Matrix::Zero(2 * n, 2 * n);
    base_.bottomLeftCorner(n, n) = -mass_.solve(system.K);
    base_.bottomRightCorner(n, n) = -mass_.solve(system.C);
    // The state scaled as (ϖ·δx, δẋ) with ϖ² = ‖M⁻¹K‖₁ (at least ω²): a similarity,
    // so the multipliers are the same, but the blocks' norms are balanced and the
    // exponentials need fewer squarings.
    scale_ = std::max(omega, std::sqrt(base_.bottomLeftCorner(n, n).cwiseAbs().colwise().sum().maxCoeff()));
    base_.topRightCorner(n, n) = scale_ * Matrix::Identity(n, n);
    base_.bottomLeftCorner(n, n) /= scale_;
  }
  // A(t) of the scaled state (ϖ·δx, δẋ).
  const Matrix& scaled_at(Real t) {
    const Index n = system_.M.rows();
    jacobians_at(basis_, system_, omega_, X_, t, Jx_, Jv_);
    A_ = base_;
    A_.bottomLeftCorner(n, n) += mass_.solve(Jx_) / scale_;
    A_.bottomRightCorner(n, n) += mass_.solve(Jv_);
    return A_;
  }
  Real scale() const { return scale_; }
  // ż = A(t)z for the columns of z, in the unscaled state (δx, δẋ).
  Matrix rate(Real t, const Matrix& z) {
    const Index n = system_.M.rows();
    jacobians_at(basis_, system_, omega_, X_, t, Jx_, Jv_);
    Matrix dz(2 * n, z.cols());
    dz.topRows(n) = z.bottomRows(n);
    dz.bottomRows(n) = -mass_.solve((system_.K - Jx_) * z.topRows(n) + (system_.C - Jv_) * z.bottomRows(n));
    return dz;
  }

 private:
  const FourierBasis& basis_;
  const PeriodicSystem& system_;
  Real omega_;
  const Vector& X_;
  Eigen::PartialPivLU<Matrix> mass_;
  Matrix base_, A_, Jx_, Jv_;
  Real scale_ = 1.0;
};

// Φ(T) by the classical Runge–Kutta method.
Matrix runge_kutta_monodromy(StateMatrix& A, Index dimension, Real T, Index steps) {
  const Real h = T / static_cast<Real>(steps);
  Matrix Phi = Matrix::Identity(dimension, dimension);
  for (Index i = 0; i < steps; ++i) {
    const Real t = h * static_cast<Real>(i);
    const Matrix k1 = A.rate(t, Phi);
    const Matrix k2 = A.rate(t + h / 2, Phi + (h / 2) * k1);
    const Matrix k3 = A.rate(t + h / 2, Phi + (h / 2) * k2);
    const Matrix k4 = A.rate(t + h, Phi + h * k3);
    Phi += (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return Phi;
}

// Φ(T) by the commutator-free exponential integrator of order four: with A₁, A₂ at
// the Gauss points t + (½ ∓ √3/6)h, Φ ← exp(h(α₂A₁ + α₁A₂))·exp(h(α₁A₁ + α₂A₂))·Φ,
// α₁,₂ = ¼ ± √3/6 (Blanes & Moan 2006; Thalhammer 2006).
Matrix exponential_monodromy(StateMatrix& A, Index dimension, Real T, Index steps) {
  const Real h = T / static_cast<Real>(steps), c = std::sqrt(3.0) / 6.0, a1 = 0.25 + c, a2 = 0.25 - c;
  Matrix Phi = Matrix::Identity(dimension, dimension), first(dimension, dimension), second(dimension, dimension);
  for (Index i = 0; i < steps; ++i) {
    const Real t = h * static_cast<Real>(i);
    const Matrix A1 = A.scaled_at(t + (0.5 - c) * h);
    const Matrix& A2 = A.scaled_at(t + (0.5 + c) * h);
    first = (h * (a1 * A1 + a2 * A2)).exp();
    second = (h * (a2 * A1 + a1 * A2)).exp();
    Phi = second * (first * Phi);
  }
  // Back to (δx, δẋ).
  const Index n = dimension / 2;
  Phi.topRightCorner(n, n) /= A.scale();
  Phi.bottomLeftCorner(n, n) *= A.scale();
  return Phi;
}

// The orbit's state velocity ż(0) = (ẋ(0), ẍ(0)) from its coefficients.
Vector state_velocity(const FourierBasis& basis, Real omega, const Vector& X) {
  const Index n = X.size() / basis.terms();
  Vector x, v;
  motion_at(basis, omega, X, 0.0, x, v);
  Vector z(2 * n);
  z.head(n) = v;
  z.tail(n).setZero();
  for (Index k = 1; k <= basis.harmonics; ++k) {
    const Real kw = static_cast<Real>(k) * omega;
    z.tail(n) -= kw * kw * X.segment((2 * k - 1) * n, n);  // at θ = 0: −(kω)² a_k
  }
  return z;
}

}  // namespace

Floquet monodromy_floquet(const FourierBasis& basis, const PeriodicSystem& system, Real omega, const Vector& X,
                          Index steps, bool autonomous, MonodromyScheme scheme) {
  if (steps < 1) throw Error("Floquet analysis: the monodromy needs at least one step");
  const Index n = system.M.rows();
  const Real T = 2 * pi / omega;
  StateMatrix A(basis, system, omega, X);
  const Matrix Phi = scheme == MonodromyScheme::exponential ? exponential_monodromy(A, 2 * n, T, steps)
                                                            : runge_kutta_monodromy(A, 2 * n, T, steps);
  if (!Phi.allFinite())
    throw Error(fmt::format(
        "Floquet analysis: the monodromy matrix is not finite after {} steps (the explicit scheme's steps are too "
        "long for the stiffest motion)",
        steps));
  Floquet out;
  out.exponents.resize(2 * n);
  Index trivial = -1;
  Matrix reduced = Phi;
  if (autonomous) {
    // The phase's multiplier is 1 with eigenvector ż(0), the orbit's own velocity; in
    // an orthonormal basis [ż(0)/‖ż(0)‖, Q] Φ is block triangular, [[1, ·], [0, QᵀΦQ]],
    // so the other 2n − 1 are QᵀΦQ's eigenvalues. Taken so rather than picked by value:
    // the orbit is the balance's, not exactly the equations', and the computed
    // phase multiplier differs from 1 by about the truncation error — as much as a
    // multiplier near 1 may.
    const Vector z0 = state_velocity(basis, omega, X);
    if (z0.norm() > 0) {
      const Eigen::HouseholderQR<Matrix> qr(z0 / z0.norm());
      const Matrix U = qr.householderQ();
      reduced = (U.transpose() * Phi * U).bottomRightCorner(2 * n - 1, 2 * n - 1);
      trivial = 2 * n - 1;
      out.exponents(trivial) = 0.0;
    }
  }
  const Eigen::EigenSolver<Matrix> eig(reduced, false);
  if (eig.info() != Eigen::Success) throw Error("Floquet analysis: the monodromy matrix's eigenvalues were not found");
  for (Index j = 0; j < reduced.rows(); ++j) out.exponents(j) = std::log(eig.eigenvalues()(j)) / T;
  finish(out, omega, autonomous, trivial);
  return out;
}

}  // namespace feran
