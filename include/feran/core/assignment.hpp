#pragma once
/// @file
/// Optimal assignment (Hungarian algorithm).

#include <vector>

#include <feran/core/types.hpp>

namespace feran {

/// Solves the rectangular assignment problem: for a cost matrix with rows ≤ cols,
/// returns for each row the column assigned to it so that every row gets a distinct
/// column and the total cost is minimal. O(rows²·cols) (Kuhn–Munkres with potentials).
std::vector<Index> optimal_assignment(const Matrix& cost);

}  // namespace feran
