#include <feran/study/sensitivity.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Dense>

namespace feran {

namespace {

// Ranks 1 … n of @p x, ties sharing their mean rank.
Vector ranks(const Vector& x) {
  const Index n = x.size();
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index(0));
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return x(a) < x(b); });
  Vector r(n);
  for (Index i = 0; i < n;) {
    Index j = i;
    while (j + 1 < n && x(order[static_cast<std::size_t>(j + 1)]) == x(order[static_cast<std::size_t>(i)])) ++j;
    for (Index k = i; k <= j; ++k) r(order[static_cast<std::size_t>(k)]) = 0.5 * static_cast<Real>(i + j) + 1;
    i = j + 1;
  }
  return r;
}

// Standardised coefficients of y on the columns of X, and R².
std::pair<std::vector<Real>, Real> standardised_fit(const Matrix& X, const Vector& y) {
  const Index n = X.rows(), d = X.cols();
  const auto sd = [n](const Vector& v) {
    return std::sqrt((v.array() - v.mean()).square().sum() / static_cast<Real>(n - 1));
  };
  const Real sy = sd(y);
  std::vector<Real> coefficients(static_cast<std::size_t>(d), 0.0);
  if (!(sy > 0)) return {coefficients, 0.0};
  Matrix A(n, d + 1);
  A.col(0).setOnes();
  A.rightCols(d) = X;
  const Vector b = A.colPivHouseholderQr().solve(y);
  for (Index j = 0; j < d; ++j) coefficients[static_cast<std::size_t>(j)] = b(j + 1) * sd(X.col(j)) / sy;
  const Vector residual = y - A * b;
  const Real r2 = 1 - residual.squaredNorm() / ((y.array() - y.mean()).square().sum());
  return {coefficients, r2};
}

}  // namespace

std::vector<Sensitivity> sensitivities(const StudySpec& study, std::span<const Evaluation> evaluations) {
  const auto d = static_cast<Index>(study.variables.size());
  std::vector<const Evaluation*> used;
  for (const auto& e : evaluations)
    if (e.evaluated) used.push_back(&e);
  const auto n = static_cast<Index>(used.size());
  std::vector<Sensitivity> out;
  for (std::size_t q = 0; q < study.quantities.size(); ++q) {
    Sensitivity s;
    s.quantity = study.quantities[q].name;
    s.samples = n;
    if (n >= d + 2) {
      Matrix X(n, d), R(n, d);
      Vector y(n);
      for (Index i = 0; i < n; ++i) {
        for (Index j = 0; j < d; ++j) X(i, j) = used[static_cast<std::size_t>(i)]->unit[static_cast<std::size_t>(j)];
        y(i) = used[static_cast<std::size_t>(i)]->quantities[q];
      }
      for (Index j = 0; j < d; ++j) R.col(j) = ranks(X.col(j));
      std::tie(s.src, s.r2) = standardised_fit(X, y);
      std::tie(s.srrc, s.r2_ranks) = standardised_fit(R, ranks(y));
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace feran
