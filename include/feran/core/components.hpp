#pragma once
/// @file
/// The connected components of a sparse matrix's graph: the sets of unknowns that no
/// entry couples (a rotor's lateral, axial and torsional motions; the separate parts
/// of a model), found by union–find (Tarjan 1975) over the entries.

#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// For each of the @p n unknowns its component in the graph whose edges are the
/// entries (i, j) of @p patterns (each n × n), the components numbered in the order
/// of their first unknowns. With @p nonzero_only, entries whose value is zero join
/// nothing; otherwise every stored entry does (a pattern of what can become
/// nonzero). Throws feran::Error for a matrix of another size.
std::vector<Index> connected_components(Index n, const std::vector<const SparseMatrix*>& patterns, bool nonzero_only);

}  // namespace feran
