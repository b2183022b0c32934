#include <feran/forces/finite_bearing.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/SparseLU>
#include <fmt/format.h>

#include <feran/core/banded_lu.hpp>
#include <feran/core/error.hpp>
#include <feran/forces/fluid_film_bearing.hpp>

namespace feran {

namespace {

// The discrete Reynolds equation L·P = F on the half bearing, in P = p·c²/(6μR²):
//   [A₊(P_{i+1} − P_i) − A₋(P_i − P_{i−1})]/Δθ² + β·B_i·(P_{j+1} − 2P_j + P_{j−1})/Δζ² = F_i,
// A± = H³ at θ_i ± Δθ/2, B_i = H³ at θ_i, H = 1 − a cos θ − b sin θ, β = (2R/L)²,
// ζ = 2z/L from the mid-plane (P_{−1} = P_1) to the end (P_m = 0), periodic in θ,
// F = Ω(a sin θ − b cos θ) − 2(ẏ cos θ + ż sin θ)/c. The circumferential positions
// are taken in the folded order 0, n−1, 1, n−2, …, so that neighbours, the periodic
// pair 0 and n−1 included, are at most two places apart. On a grid with 2m ≤ n the
// unknowns are numbered ring by ring (k = fold(i)·m + j): the matrix is banded, of
// half-bandwidth 2m. On a grid finer axially than that (n < 2m) they are numbered
// along each axial station's circle instead (k = j·n + fold(i)), of half-bandwidth n:
// 40 × 50 cells have a band of 40 rather than 100, and factorise as a band.
class Film {
 public:
  Film(const JournalBearingGeometry& g, const FiniteBearingGrid& grid, const Eigen::Vector2d& x)
      : n_(grid.circumferential),
        m_(grid.axial),
        dt_(2 * pi / n_),
        dz_(1.0 / m_),
        beta_(std::pow(g.diameter / g.length, 2)),
        a_(x(0) / g.clearance),
        b_(x(1) / g.clearance),
        rings_first_(2 * m_ <= n_) {}

  Index size() const { return static_cast<Index>(n_) * m_; }
  Index bandwidth() const { return rings_first_ ? 2 * static_cast<Index>(m_) : static_cast<Index>(n_); }
  Index k(int i, int j) const {
    const int r = ((i % n_) + n_) % n_;
    const Index folded = 2 * r < n_ ? 2 * r : 2 * (n_ - 1 - r) + 1;
    return rings_first_ ? folded * m_ + j : static_cast<Index>(j) * n_ + folded;
  }
  Real theta(Real i) const { return i * dt_; }
  Real H(Real th) const { return 1.0 - a_ * std::cos(th) - b_ * std::sin(th); }
  // ∂(H³)/∂(a, b) at θ: 3H²·(−cos θ, −sin θ).
  Eigen::Vector2d dH3(Real th) const {
    const Real h = H(th);
    return {-3.0 * h * h * std::cos(th), -3.0 * h * h * std::sin(th)};
  }
  // −L, the discrete operator of the whole film (FilmSolver replaces the cavitated
  // rows by the identity).
  SparseMatrix system() const {
    std::vector<Eigen::Triplet<Real>> t;
    t.reserve(static_cast<std::size_t>(5 * size()));
    for (int i = 0; i < n_; ++i) {
      const Real ap = std::pow(H(theta(i + 0.5)), 3), am = std::pow(H(theta(i - 0.5)), 3);
      const Real bz = beta_ * std::pow(H(theta(i)), 3) / (dz_ * dz_);
      for (int j = 0; j < m_; ++j) {
        const Index row = k(i, j);
        t.emplace_back(row, row, (ap + am) / (dt_ * dt_) + 2.0 * bz);
        t.emplace_back(row, k(i + 1, j), -ap / (dt_ * dt_));
        t.emplace_back(row, k(i - 1, j), -am / (dt_ * dt_));
        if (j + 1 < m_) t.emplace_back(row, k(i, j + 1), j == 0 ? -2.0 * bz : -bz);
        if (j > 0) t.emplace_back(row, k(i, j - 1), -bz);
      }
    }
    SparseMatrix S(size(), size());
    S.setFromTriplets(t.begin(), t.end());
    return S;
  }
  // (L_d·P) with the derivative of H³ along (a, b) component @p d in place of H³.
  Vector derivative_times(int d, const Vector& P) const {
    Vector out(size());
    for (int i = 0; i < n_; ++i) {
      const Real ap = dH3(theta(i + 0.5))(d), am = dH3(theta(i - 0.5))(d);
      const Real bz = beta_ * dH3(theta(i))(d) / (dz_ * dz_);
      for (int j = 0; j < m_; ++j) {
        const Real p = P(k(i, j)), up = j + 1 < m_ ? P(k(i, j + 1)) : 0.0, down = j > 0 ? P(k(i, j - 1)) : up;
        out(k(i, j)) =
            (ap * (P(k(i + 1, j)) - p) - am * (p - P(k(i - 1, j)))) / (dt_ * dt_) + bz * (up - 2.0 * p + down);
      }
    }
    return out;
  }
  // Quadrature weights of ∫₀¹∫₀^{2π} P·(cos θ, sin θ) dθ dζ: periodic trapezoid in θ;
  // in ζ composite Simpson for an even number of cells (exact for the short
  // bearing's parabola, which the differences also hold exactly), else trapezoid.
  Real weight(int j) const {
    if (m_ % 2 != 0) return dt_ * dz_ * (j == 0 ? 0.5 : 1.0);
    return dt_ * dz_ / 3.0 * (j == 0 ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0));
  }
  int n() const { return n_; }
  int m() const { return m_; }

 private:
  int n_, m_;
  Real dt_, dz_, beta_, a_, b_;
  bool rings_first_;
};

// −L with the rows of the cavitated nodes replaced by the identity, factorised: by
// the banded LU without pivoting where the band is small (−L is an irreducibly
// diagonally dominant M-matrix, and so is it with identity rows, for which Gaussian
// elimination without pivoting is stable; Golub & Van Loan 2013, §4.4), by Eigen's
// sparse LU otherwise or should a pivot nevertheless be small.
class FilmSolver {
 public:
  // The band is taken up to 2²³ entries (64 MB): a static analysis on 66 × 33 cells
  // (half-bandwidth 66) took 0.13 s so against 0.68 s by the sparse LU, on 400 × 60
  // (120) 13.5 s against 27.8 s. Beyond, the band's storage and its b² flops per
  // unknown grow past the sparse LU's fill.
  static constexpr Index max_band_entries = Index{1} << 23;
  FilmSolver(const SparseMatrix& full, Index bandwidth) : matrix_(full) {
    if (bandwidth <= 64 || full.rows() * (2 * bandwidth + 1) <= max_band_entries) {
      // The band's storage (150 kB on the default grid) is kept by each thread:
      // allocated per call it would be mapped and faulted in anew every time.
      thread_local BandedLU band;
      band_ = &band;
      band_->resize(full.rows(), bandwidth);
      positions_ = band_->positions(matrix_);
    }
  }
  void factorize(const std::vector<char>& active) {
    // Rows of active (cavitated) nodes: the identity, the other entries kept as
    // explicit zeros so that one pattern (and one symbolic analysis) serves all.
    const Real* value = matrix_.valuePtr();
    for (Index col = 0; col < matrix_.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(matrix_, col); it; ++it) {
        const auto e = static_cast<std::size_t>(&it.valueRef() - value);
        it.valueRef() = active[static_cast<std::size_t>(it.row())] ? (it.row() == col ? 1.0 : 0.0) : values_[e];
      }
    banded_ = false;
    if (!positions_.empty()) {
      band_->set_zero();
      band_->add(1.0, matrix_, positions_);
      banded_ = band_->factorize();
    }
    if (!banded_) {
      if (!analysed_) {
        sparse_.analyzePattern(matrix_);
        analysed_ = true;
      }
      sparse_.factorize(matrix_);
      if (sparse_.info() != Eigen::Success)
        throw Error("finite-length bearing: the discrete Reynolds equation is singular");
    }
  }
  Vector solve(const Vector& rhs) const {
    if (!banded_) return sparse_.solve(rhs);
    Vector x = rhs;
    band_->solve_in_place(x);
    return x;
  }

 private:
  SparseMatrix matrix_;
  std::vector<Real> values_{matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros()};
  BandedLU* band_ = nullptr;
  std::vector<Index> positions_;
  bool banded_ = false, analysed_ = false;
  mutable Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> sparse_;
};

}  // namespace

FilmForce finite_bearing_force(const JournalBearingGeometry& g, const FiniteBearingGrid& grid, Real speed,
                               Eigen::Vector2d x, const Eigen::Vector2d& v) {
  if (grid.circumferential < 8 || grid.axial < 1)
    throw Error(fmt::format("a finite-length bearing needs at least 8 circumferential and 1 axial cells, got {} and {}",
                            grid.circumferential, grid.axial));
  const Real c = g.clearance, R = 0.5 * g.diameter;
  // A journal at rest at the very centre has no pressure anywhere, though the
  // Jacobian has a limit: taken at a displacement of 1e-9 c, as for the short bearing.
  if (x.norm() < 1e-9 * c && v.norm() == 0.0) x = Eigen::Vector2d(1e-9 * c, 0.0);
  const Film film(g, grid, x);
  const Index N = film.size();
  // F and its derivatives with respect to y, z, ẏ, ż.
  Vector F(N);
  Matrix dF(N, 4);
  for (int i = 0; i < film.n(); ++i) {
    const Real th = film.theta(i), ct = std::cos(th), st = std::sin(th);
    const Real value = speed * (x(0) * st - x(1) * ct) / c - 2.0 * (v(0) * ct + v(1) * st) / c;
    for (int j = 0; j < film.m(); ++j) {
      const Index row = film.k(i, j);
      F(row) = value;
      dF.row(row) << speed * st / c, -speed * ct / c, -2.0 * ct / c, -2.0 * st / c;
    }
  }
  // −L·P = −F where the film is full; P = 0 where it has cavitated (Reynolds) — the
  // active set of the complementarity problem P ≥ 0, −L·P + F ≥ 0, P·(−L·P + F) = 0,
  // found by the primal–dual active-set iteration (Hintermüller, Ito & Kunisch 2003)
  // from the diverging part of the film (F > 0); it ends when the set repeats.
  const bool reynolds = grid.cavitation == Cavitation::reynolds;
  std::vector<char> active(static_cast<std::size_t>(N), 0);
  if (reynolds)
    for (Index k = 0; k < N; ++k) active[static_cast<std::size_t>(k)] = F(k) > 0 ? 1 : 0;
  Vector P;
  const SparseMatrix full = film.system();
  FilmSolver lu(full, film.bandwidth());
  for (int iteration = 0;; ++iteration) {
    lu.factorize(active);
    Vector rhs = -F;
    for (Index k = 0; k < N; ++k)
      if (active[static_cast<std::size_t>(k)]) rhs(k) = 0.0;
    P = lu.solve(rhs);
    if (!reynolds) break;
    const Vector lambda = full * P + F;  // the film's inflow where cavitated: ≥ 0 at the solution
    const Real scale = F.cwiseAbs().maxCoeff() + 1e-300, pscale = P.cwiseAbs().maxCoeff() + 1e-300;
    std::vector<char> next(active.size());
    for (Index k = 0; k < N; ++k) {
      const auto s = static_cast<std::size_t>(k);
      next[s] = active[s] ? (lambda(k) > 1e-13 * scale ? 1 : 0) : (P(k) < -1e-13 * pscale ? 1 : 0);
    }
    if (next == active) break;
    if (iteration == 100)
      throw Error("finite-length bearing: the cavitated region was not found in 100 active-set iterations");
    active = std::move(next);
  }
  // dP/dq from the same factorisation: −L·dP = dF·(−1) + (dL/dq)·P on the full film,
  // dP = 0 where cavitated (Reynolds); for Gümbel's condition the whole film, the
  // force taking only its positive part.
  Matrix rhs(N, 4);
  for (int col = 0; col < 4; ++col) rhs.col(col) = -dF.col(col);
  for (int d = 0; d < 2; ++d) rhs.col(d) += film.derivative_times(d, P) / c;
  for (Index k = 0; k < N; ++k)
    if (active[static_cast<std::size_t>(k)]) rhs.row(k).setZero();
  Matrix dP(N, 4);
  for (int col = 0; col < 4; ++col) dP.col(col) = lu.solve(rhs.col(col));
  // f = −R·L·(6μR²/c²)·Σ w·P⁺·(cos θ, sin θ).
  const Real scale = -R * g.length * 6.0 * g.viscosity * R * R / (c * c);
  FilmForce out;
  out.peak_pressure = std::max(0.0, P.maxCoeff()) * 6.0 * g.viscosity * R * R / (c * c);
  for (int i = 0; i < film.n(); ++i) {
    const Real th = film.theta(i);
    const Eigen::Vector2d normal(std::cos(th), std::sin(th));
    for (int j = 0; j < film.m(); ++j) {
      const Index k = film.k(i, j);
      if (!(P(k) > 0)) continue;
      const Real w = scale * film.weight(j);
      out.f += w * P(k) * normal;
      out.dfdx += w * normal * dP.row(k).head<2>();
      out.dfdv += w * normal * dP.row(k).tail<2>();
    }
  }
  return out;
}

}  // namespace feran
