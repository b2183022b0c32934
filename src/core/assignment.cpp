#include <feran/core/assignment.hpp>

#include <limits>
#include <stdexcept>

namespace feran {

std::vector<Index> optimal_assignment(const Matrix& cost) {
  const Index n = cost.rows(), m = cost.cols();
  if (n > m) throw std::invalid_argument("optimal_assignment: more rows than columns");
  const Real inf = std::numeric_limits<Real>::infinity();
  // Shortest augmenting paths with row potentials u and column potentials v
  // (1-based internally; column 0 is the virtual start).
  std::vector<Real> u(static_cast<std::size_t>(n + 1), 0.0), v(static_cast<std::size_t>(m + 1), 0.0);
  std::vector<Index> match(static_cast<std::size_t>(m + 1), 0), way(static_cast<std::size_t>(m + 1), 0);
  for (Index i = 1; i <= n; ++i) {
    match[0] = i;
    Index j0 = 0;
    std::vector<Real> minv(static_cast<std::size_t>(m + 1), inf);
    std::vector<bool> used(static_cast<std::size_t>(m + 1), false);
    do {
      used[static_cast<std::size_t>(j0)] = true;
      const Index i0 = match[static_cast<std::size_t>(j0)];
      Real delta = inf;
      Index j1 = 0;
      for (Index j = 1; j <= m; ++j) {
        if (used[static_cast<std::size_t>(j)]) continue;
        const Real cur = cost(i0 - 1, j - 1) - u[static_cast<std::size_t>(i0)] - v[static_cast<std::size_t>(j)];
        if (cur < minv[static_cast<std::size_t>(j)]) {
          minv[static_cast<std::size_t>(j)] = cur;
          way[static_cast<std::size_t>(j)] = j0;
        }
        if (minv[static_cast<std::size_t>(j)] < delta) {
          delta = minv[static_cast<std::size_t>(j)];
          j1 = j;
        }
      }
      for (Index j = 0; j <= m; ++j) {
        if (used[static_cast<std::size_t>(j)]) {
          u[static_cast<std::size_t>(match[static_cast<std::size_t>(j)])] += delta;
          v[static_cast<std::size_t>(j)] -= delta;
        } else {
          minv[static_cast<std::size_t>(j)] -= delta;
        }
      }
      j0 = j1;
    } while (match[static_cast<std::size_t>(j0)] != 0);
    do {
      const Index j1 = way[static_cast<std::size_t>(j0)];
      match[static_cast<std::size_t>(j0)] = match[static_cast<std::size_t>(j1)];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<Index> row_to_col(static_cast<std::size_t>(n), -1);
  for (Index j = 1; j <= m; ++j)
    if (match[static_cast<std::size_t>(j)] > 0)
      row_to_col[static_cast<std::size_t>(match[static_cast<std::size_t>(j)] - 1)] = j - 1;
  return row_to_col;
}

}  // namespace feran
