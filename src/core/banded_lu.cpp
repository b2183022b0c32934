#include <feran/core/banded_lu.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <feran/core/error.hpp>

namespace feran {

Index BandedLU::half_bandwidth(const SparseMatrix& pattern) {
  Index b = 0;
  for (Index k = 0; k < pattern.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(pattern, k); it; ++it) b = std::max(b, std::abs(it.row() - it.col()));
  return b;
}

void BandedLU::resize(Index n, Index b) {
  n_ = n;
  b_ = std::min(b, std::max<Index>(n - 1, 0));
  ld_ = 2 * b_ + 1;
  a_.assign(static_cast<std::size_t>(n_ * ld_), 0.0);
}

void BandedLU::set_zero() { std::fill(a_.begin(), a_.end(), 0.0); }

void BandedLU::add(Real c, const SparseMatrix& S) {
  if (S.rows() != n_ || S.cols() != n_) throw Error("BandedLU::add: a matrix of another size");
  for (Index k = 0; k < S.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(S, k); it; ++it) {
      if (std::abs(it.row() - it.col()) > b_) throw Error("BandedLU::add: an entry outside the band");
      at(it.row(), it.col()) += c * it.value();
    }
}

std::vector<Index> BandedLU::positions(const SparseMatrix& S) const {
  if (S.rows() != n_ || S.cols() != n_ || !S.isCompressed()) throw Error("BandedLU::positions: a matrix of another size, or not compressed");
  std::vector<Index> out;
  out.reserve(static_cast<std::size_t>(S.nonZeros()));
  for (Index k = 0; k < S.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(S, k); it; ++it) {
      if (std::abs(it.row() - it.col()) > b_) throw Error("BandedLU::positions: an entry outside the band");
      out.push_back(it.col() * ld_ + (it.row() - it.col() + b_));
    }
  return out;
}

void BandedLU::add(Real c, const SparseMatrix& S, const std::vector<Index>& positions) {
  const Real* v = S.valuePtr();
  Real* a = a_.data();
  const std::size_t n = positions.size();
  for (std::size_t e = 0; e < n; ++e) a[positions[e]] += c * v[e];
}

bool BandedLU::factorize() {
  constexpr Real smallest_pivot = 1e-10;
  for (Index k = 0; k < n_; ++k) {
    Real* ck = a_.data() + k * ld_;
    const Index m = std::min(b_, n_ - 1 - k);  // rows below the diagonal in the band
    const Real p = ck[b_];
    Real largest = std::abs(p);
    for (Index i = 1; i <= m; ++i) largest = std::max(largest, std::abs(ck[b_ + i]));
    if (!std::isfinite(p) || !(std::abs(p) > smallest_pivot * largest)) return false;
    const Real inverse = 1.0 / p;
    Real* l = ck + b_ + 1;  // L(k + 1 … k + m, k)
    for (Index i = 0; i < m; ++i) l[i] *= inverse;
    // The trailing block: column k + j, rows k + 1 … k + m, less L·U(k, k + j).
    for (Index j = 1; j <= m; ++j) {
      Real* cj = a_.data() + (k + j) * ld_;
      const Real u = cj[b_ - j];  // U(k, k + j)
      if (u == 0.0) continue;
      Real* d = cj + (b_ - j + 1);
      for (Index i = 0; i < m; ++i) d[i] -= l[i] * u;
    }
  }
  return true;
}

void BandedLU::solve_in_place(Vector& x) const {
  Real* y = x.data();
  for (Index k = 0; k < n_; ++k) {  // L·y = b, unit diagonal
    const Real* l = a_.data() + k * ld_ + b_ + 1;
    const Index m = std::min(b_, n_ - 1 - k);
    const Real yk = y[k];
    for (Index i = 0; i < m; ++i) y[k + 1 + i] -= l[i] * yk;
  }
  for (Index k = n_ - 1; k >= 0; --k) {  // U·x = y
    const Real* ck = a_.data() + k * ld_;
    y[k] /= ck[b_];
    const Index m = std::min(b_, k);
    const Real xk = y[k];
    for (Index i = 1; i <= m; ++i) y[k - i] -= ck[b_ - i] * xk;
  }
}

}  // namespace feran
