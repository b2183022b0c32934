#pragma once
/// @file
/// Orderings of a sparse matrix's unknowns that narrow its band: the reverse
/// Cuthill–McKee ordering (Cuthill & McKee 1969; reversed, its envelope is never
/// larger: Liu & Sherman, SIAM J. Numer. Anal. 13, 1976) started at a
/// pseudo-peripheral node (George & Liu, "Computer Solution of Large Sparse Positive
/// Definite Systems", 1981, §4.3). A rotor's
/// unknowns in node order already form a narrow band; a model whose supports or
/// second shaft line join nodes far apart in that order does not, and this ordering
/// gives it one of about the width of its widest level structure.

#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// The neighbours of each of @p n unknowns in the graph of @p patterns' entries (each
/// n × n; an entry (i, j) joins i and j both ways), each list sorted, without i
/// itself. Throws feran::Error for a matrix of another size.
std::vector<std::vector<Index>> pattern_graph(Index n, const std::vector<const SparseMatrix*>& patterns);
/// The same for one complex matrix (square).
std::vector<std::vector<Index>> pattern_graph(const Eigen::SparseMatrix<Complex>& pattern);

/// The reverse Cuthill–McKee order of @p graph (symmetric neighbour lists): the
/// unknown at each position. Each connected component is numbered from a
/// pseudo-peripheral node, breadth first, neighbours by increasing degree (ties by
/// index, so the order is deterministic), and the whole reversed.
std::vector<Index> reverse_cuthill_mckee(const std::vector<std::vector<Index>>& graph);

/// The half-bandwidth of @p graph with unknown i at position @p position_of[i].
Index ordered_bandwidth(const std::vector<std::vector<Index>>& graph, const std::vector<Index>& position_of);

}  // namespace feran
