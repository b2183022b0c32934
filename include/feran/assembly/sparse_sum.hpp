#pragma once
/// @file
/// Σ c_k·A_k over sparse matrices of fixed patterns, written in place into a matrix
/// of their union's pattern: for the tangents of time integration, which a speed ramp
/// recombines at every step (D = C + Ω·G, K + Ω·K_i) and which Eigen's sparse sums
/// would allocate anew each time.

#include <vector>

#include <feran/core/types.hpp>

namespace feran {

class SparseSum {
 public:
  SparseSum() = default;
  /// The union of the terms' patterns (all of one size); the terms given to
  /// evaluate() must have these patterns, in this order.
  explicit SparseSum(const std::vector<const SparseMatrix*>& terms);

  /// out = Σ c[k]·terms[k]; @p out takes the union's pattern when it has another.
  void evaluate(const std::vector<Real>& c, const std::vector<const SparseMatrix*>& terms, SparseMatrix& out) const;
  /// Where entry (@p row, @p col) of the union lies in the values of evaluate()'s
  /// result; throws when the union has no such entry.
  Index position(Index row, Index col) const;

 private:
  SparseMatrix pattern_;                   // the union, values zero
  std::vector<std::vector<Index>> where_;  // per term: each entry's index in pattern_'s values
};

}  // namespace feran
