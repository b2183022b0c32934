#include <feran/core/components.hpp>

#include <algorithm>

#include <feran/core/error.hpp>

namespace feran {

std::vector<Index> connected_components(Index n, const std::vector<const SparseMatrix*>& patterns, bool nonzero_only) {
  std::vector<Index> parent(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) parent[static_cast<std::size_t>(i)] = i;
  const auto root = [&](Index i) {
    while (parent[static_cast<std::size_t>(i)] != i)
      i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
  };
  for (const SparseMatrix* A : patterns) {
    if (A->rows() != n || A->cols() != n) throw Error("connected_components: a matrix of another size");
    for (Index j = 0; j < A->outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(*A, j); it; ++it) {
        if (nonzero_only && it.value() == 0.0) continue;
        const Index a = root(it.row()), b = root(it.col());
        if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
      }
  }
  // Each root is its component's smallest unknown: numbering the roots as they come
  // orders the components by their first unknowns.
  std::vector<Index> number(static_cast<std::size_t>(n), -1), component(static_cast<std::size_t>(n));
  Index count = 0;
  for (Index i = 0; i < n; ++i) {
    Index& c = number[static_cast<std::size_t>(root(i))];
    if (c < 0) c = count++;
    component[static_cast<std::size_t>(i)] = c;
  }
  return component;
}

}  // namespace feran
