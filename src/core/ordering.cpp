#include <feran/core/ordering.hpp>

#include <algorithm>
#include <cstdlib>

#include <feran/core/error.hpp>

namespace feran {

namespace {

template <class Sparse>
void add_edges(std::vector<std::vector<Index>>& graph, const Sparse& A) {
  const auto n = static_cast<Index>(graph.size());
  if (A.rows() != n || A.cols() != n) throw Error("pattern_graph: a matrix of another size");
  for (Index j = 0; j < A.outerSize(); ++j)
    for (typename Sparse::InnerIterator it(A, j); it; ++it)
      if (it.row() != it.col()) {
        graph[static_cast<std::size_t>(it.row())].push_back(it.col());
        graph[static_cast<std::size_t>(it.col())].push_back(it.row());
      }
}

void sort_unique(std::vector<std::vector<Index>>& graph) {
  for (std::vector<Index>& adjacent : graph) {
    std::sort(adjacent.begin(), adjacent.end());
    adjacent.erase(std::unique(adjacent.begin(), adjacent.end()), adjacent.end());
  }
}

}  // namespace

std::vector<std::vector<Index>> pattern_graph(Index n, const std::vector<const SparseMatrix*>& patterns) {
  std::vector<std::vector<Index>> graph(static_cast<std::size_t>(n));
  for (const SparseMatrix* A : patterns) add_edges(graph, *A);
  sort_unique(graph);
  return graph;
}

std::vector<std::vector<Index>> pattern_graph(const Eigen::SparseMatrix<Complex>& pattern) {
  std::vector<std::vector<Index>> graph(static_cast<std::size_t>(pattern.rows()));
  add_edges(graph, pattern);
  sort_unique(graph);
  return graph;
}

namespace {

// The breadth-first levels from @p root over the nodes of its component not yet
// numbered (mark ≥ 0), each reached marked with @p stamp: the nodes in level order,
// and where each level starts (with the end).
struct Levels {
  std::vector<Index> nodes;
  std::vector<std::size_t> starts;
};

Levels level_structure(const std::vector<std::vector<Index>>& graph, Index root, std::vector<int>& mark, int stamp) {
  Levels out;
  out.nodes.push_back(root);
  mark[static_cast<std::size_t>(root)] = stamp;
  std::size_t begin = 0;
  while (begin < out.nodes.size()) {
    out.starts.push_back(begin);
    const std::size_t end = out.nodes.size();
    for (std::size_t k = begin; k < end; ++k)
      for (const Index j : graph[static_cast<std::size_t>(out.nodes[k])])
        if (mark[static_cast<std::size_t>(j)] != stamp && mark[static_cast<std::size_t>(j)] >= 0) {
          mark[static_cast<std::size_t>(j)] = stamp;
          out.nodes.push_back(j);
        }
    begin = end;
  }
  out.starts.push_back(out.nodes.size());
  return out;
}

}  // namespace

std::vector<Index> reverse_cuthill_mckee(const std::vector<std::vector<Index>>& graph) {
  const auto n = static_cast<Index>(graph.size());
  auto degree = [&](Index i) { return graph[static_cast<std::size_t>(i)].size(); };
  // mark: -1 numbered; otherwise the stamp of the last level structure that reached it.
  std::vector<int> mark(static_cast<std::size_t>(n), 0);
  int stamp = 0;
  std::vector<Index> order;
  order.reserve(static_cast<std::size_t>(n));
  for (Index start = 0; start < n; ++start) {
    if (mark[static_cast<std::size_t>(start)] < 0) continue;
    // A pseudo-peripheral root: from the component's first node, move to a node of
    // least degree in the last level while that deepens the level structure.
    Index root = start;
    Levels levels = level_structure(graph, root, mark, ++stamp);
    for (;;) {
      Index candidate = -1;
      for (std::size_t k = levels.starts[levels.starts.size() - 2]; k < levels.nodes.size(); ++k) {
        const Index i = levels.nodes[k];
        if (candidate < 0 || degree(i) < degree(candidate) || (degree(i) == degree(candidate) && i < candidate))
          candidate = i;
      }
      Levels next = level_structure(graph, candidate, mark, ++stamp);
      if (next.starts.size() <= levels.starts.size()) break;
      root = candidate;
      levels = std::move(next);
    }
    // Cuthill–McKee from the root: each node's unnumbered neighbours by increasing
    // degree.
    const std::size_t first = order.size();
    order.push_back(root);
    mark[static_cast<std::size_t>(root)] = -1;
    std::vector<Index> adjacent;
    for (std::size_t k = first; k < order.size(); ++k) {
      adjacent.clear();
      for (const Index j : graph[static_cast<std::size_t>(order[k])])
        if (mark[static_cast<std::size_t>(j)] >= 0) adjacent.push_back(j);
      std::sort(adjacent.begin(), adjacent.end(),
                [&](Index a, Index b) { return degree(a) != degree(b) ? degree(a) < degree(b) : a < b; });
      for (const Index j : adjacent) {
        mark[static_cast<std::size_t>(j)] = -1;
        order.push_back(j);
      }
    }
  }
  std::reverse(order.begin(), order.end());
  return order;
}

Index ordered_bandwidth(const std::vector<std::vector<Index>>& graph, const std::vector<Index>& position_of) {
  Index b = 0;
  for (std::size_t i = 0; i < graph.size(); ++i)
    for (const Index j : graph[i]) b = std::max(b, std::abs(position_of[i] - position_of[static_cast<std::size_t>(j)]));
  return b;
}

}  // namespace feran
